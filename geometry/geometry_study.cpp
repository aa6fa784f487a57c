#include "geometry/geometry_study.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "geometry/rsd/surface_measures.hpp"
#include "geometry/surface_from_config.hpp"
#include "geometry/surface_patches.hpp"

namespace iga {

bool is_geometry_study(const ConfigNode& root) { return root.has("study"); }

GeometryStudySettings parse_geometry_study(const ConfigNode& root, const std::string& config_path,
                                           int levels_override, const std::string& output_override) {
  root.check_keys({"study", "domain", "output"});
  GeometryStudySettings s(root);
  const ConfigNode study = root["study"];
  study.check_keys({"type", "levels", "reference", "surface_files_up_to_level"});
  study["type"].as_choice({"geometry"});
  if (const auto levels = study.find("levels")) {
    s.levels = levels->as_int();
    if (s.levels < 1 || s.levels > 7) levels->fail("levels must be between 1 and 7 (icosphere levels 0..6)");
  }
  if (levels_override > 0) {
    if (levels_override > 7) study.fail("--levels must be at most 7 for a geometry study");
    s.levels = levels_override;
  }
  const ConfigNode reference = study["reference"];
  reference.check_keys({"type", "center", "radius"});
  reference["type"].as_choice({"sphere"});
  if (const auto center = reference.find("center")) {
    const std::vector<double> c = center->as_doubles();
    if (c.size() != 3) center->fail("center needs three coordinates [x, y, z]");
    s.center = Eigen::Vector3d(c[0], c[1], c[2]);
  }
  if (const auto radius = reference.find("radius")) {
    s.radius = radius->as_double();
    if (!(s.radius > 0.0) || !std::isfinite(s.radius)) radius->fail("radius must be a positive number");
  }
  if (const auto files = study.find("surface_files_up_to_level")) {
    s.surface_files_up_to_level = files->as_int();
    if (s.surface_files_up_to_level < 0) files->fail("surface_files_up_to_level must be >= 0");
  }
  // The domain is checked by building its coarsest surface (cheap), so a typo fails before the study.
  surface_mesh_from_config(root["domain"], 0);
  rsd_options_from_config(root["domain"]);

  s.output_dir = "results/" + std::filesystem::path(config_path).stem().string();
  if (const auto output = root.find("output")) {
    output->check_keys({"directory", "vtk"});
    if (const auto dir = output->find("directory")) s.output_dir = dir->as_string();
    if (const auto vtk = output->find("vtk")) {
      if (vtk->is_scalar()) {
        s.write_vtk = vtk->as_bool();
      } else {
        vtk->check_keys({"enabled", "samples"});
        s.write_vtk = vtk->get_bool("enabled", true);
        if (const auto samples = vtk->find("samples")) {
          s.vtk_samples = samples->as_int();
          if (s.vtk_samples < 1 || s.vtk_samples > 64) samples->fail("samples must be between 1 and 64");
        }
      }
    }
  }
  if (!output_override.empty()) s.output_dir = output_override;
  return s;
}

std::vector<GeometryLevel> run_geometry_study(const GeometryStudySettings& settings,
                                              const std::function<void(const std::string&)>& progress,
                                              const std::function<void(const GeometryLevel&)>& on_level) {
  std::vector<GeometryLevel> rows;
  const ConfigNode domain = settings.root["domain"];
  const double area = 4.0 * M_PI * settings.radius * settings.radius;
  const double volume = area * settings.radius / 3.0;
  for (int level = 0; level < settings.levels; ++level) {
    const std::string tag = "[level " + std::to_string(level) + "] ";
    progress(tag + "building the surface");
    const auto t0 = std::chrono::steady_clock::now();
    GeometryLevel row;
    row.level = level;
    row.surface = std::make_shared<const rsd::RsdSurface>(surface_from_config(domain, level));
    const rsd::RsdSurface& surface = *row.surface;
    row.triangles = surface.mesh.num_triangles();
    for (const auto& t : surface.mesh.triangles)
      for (int c = 0; c < 3; ++c)
        row.h = std::max(row.h, (surface.mesh.points[t[c]] - surface.mesh.points[t[(c + 1) % 3]]).norm());
    progress(tag + "measuring " + std::to_string(row.triangles) + " patches");
    const rsd::SphereDeviation d = rsd::sphere_deviation(surface, settings.center, settings.radius);
    // (1/3)∫ x·n over a closed surface is its enclosed volume wherever the origin is.
    const rsd::AreaVolume av = rsd::area_and_volume(surface);
    row.radial = d.radial;
    row.normal_degrees = d.normal_degrees;
    row.area_error = std::abs(av.area / area - 1.0);
    row.volume_error = std::abs(av.volume / volume - 1.0);
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, "%.3f s", std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    progress(tag + "done in " + seconds);
    row.patches = surface_patches_of(surface);
    if (on_level) on_level(row);
    // The rows keep the numbers; the patches of a fine level are large.
    row.surface.reset();
    row.patches.patches.clear();
    row.patches.vertices.clear();
    rows.push_back(std::move(row));
  }
  return rows;
}

}  // namespace iga
