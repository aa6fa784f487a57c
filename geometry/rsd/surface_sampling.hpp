#pragma once
/// @file
/// A fine triangulation of a patch surface (an RSD surface, or any SurfacePatches) for drawing: every patch split into s² sub-triangles
/// on the uniform barycentric lattice, points shared between neighbouring patches (the edges
/// are parametrised identically), unit normals F_ξ × F_η of the surface at every point (continuous
/// across edges because the surface is G1).

#include <array>
#include <vector>

#include "geometry/rsd/rsd_surface.hpp"
#include "geometry/surface_patches.hpp"

namespace iga::rsd {

struct SampledSurface {
  std::vector<Eigen::Vector3d> points;
  std::vector<Eigen::Vector3d> normals;      ///< unit, oriented like the mesh triangles
  std::vector<std::array<int, 3>> triangles;  ///< oriented like the mesh triangles
  std::vector<int> patch;                     ///< the patch (mesh triangle) of each sub-triangle
};

/// Samples `surface` with `subdivisions` ≥ 1 segments per patch edge.
SampledSurface sample_surface(const SurfacePatches& surface, int subdivisions);
SampledSurface sample_surface(const RsdSurface& surface, int subdivisions);

}  // namespace iga::rsd
