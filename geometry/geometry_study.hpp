#pragma once
/// @file
/// A geometry study: the smooth surface itself converging to a known surface as its mesh is
/// refined, with no PDE. Config (docs/configuration.md, "Geometry studies"):
///
///   study:
///     type: geometry
///     levels: 6                    # icosphere levels 0..5 (1..7)
///     reference: {type: sphere, center: [0, 0, 0], radius: 1}
///     surface_files_up_to_level: 3 # surface files of levels 0..3 only (default: every level)
///   domain: {type: surface, mesh: icosphere, normals: exact}   # no level: the study sets it
///   output: {directory: results/..., vtk: {samples: 4}}
///
/// A geometry study has no problem, space or refinement section. Per level it reports the
/// radial (max ||F − c| − r|), normal (max angle between the surface normal and F − c, degrees),
/// relative area and relative volume errors against the sphere, and the surface's own report
/// (G1 residual, fold indicator, regularity, interpolation residual).

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "config/config_node.hpp"
#include "geometry/rsd/rsd_surface.hpp"
#include "geometry/surface_patches.hpp"

namespace iga {

struct GeometryStudySettings {
  explicit GeometryStudySettings(ConfigNode root_node) : root(std::move(root_node)) {}
  ConfigNode root;
  int levels = 4;
  Eigen::Vector3d center = Eigen::Vector3d::Zero();  ///< reference sphere
  double radius = 1.0;
  int surface_files_up_to_level = -1;  ///< -1: every level
  std::string output_dir;
  bool write_vtk = true;
  int vtk_samples = 4;
};

/// True when `root` asks for a geometry study (a `study` section).
bool is_geometry_study(const ConfigNode& root);

/// Validates the whole config before anything is built (levels_override > 0 replaces
/// study.levels; output_override replaces output.directory).
GeometryStudySettings parse_geometry_study(const ConfigNode& root, const std::string& config_path,
                                           int levels_override, const std::string& output_override);

struct GeometryLevel {
  int level = 0;
  int triangles = 0;
  double h = 0;                 ///< longest mesh edge
  double radial = 0, normal_degrees = 0;
  double area_error = 0, volume_error = 0;  ///< relative to the sphere's
  std::shared_ptr<const rsd::RsdSurface> surface;  ///< during on_level only (then released)
  SurfacePatches patches;  ///< the surface's patches (during on_level only) and report (kept)
};

/// Builds and measures every level, handing each to `on_level` before the next is built; the
/// returned rows keep the numbers and reports, not the surfaces.
std::vector<GeometryLevel> run_geometry_study(const GeometryStudySettings& settings,
                                              const std::function<void(const std::string&)>& progress,
                                              const std::function<void(const GeometryLevel&)>& on_level = {});

}  // namespace iga
