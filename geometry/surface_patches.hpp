#pragma once
/// @file
/// A smooth surface as the outputs see it, whatever built it: triangular Bézier patches over the
/// triangles of a mesh (neighbouring patches parametrise their shared edge identically), and the
/// construction's report. Spaces on such surfaces hand it out (Space::surface_patches) so that
/// the output layer can write the surface (output/bernstein_patches.hpp, output/surface_files.hpp)
/// and its report (summary.json) without knowing the construction.

#include <array>
#include <string>
#include <utility>
#include <vector>

#include "geometry/rsd/bezier_triangle.hpp"

namespace iga {

namespace rsd {
struct RsdSurface;
}

struct SurfacePatches {
  std::vector<BezierTriangle> patches;       ///< one per mesh triangle
  std::vector<std::array<int, 3>> vertices;  ///< mesh vertices of each patch (t_a = 1 at vertices[n][a])
  /// Words of the report, e.g. ("construction", "rsd"), ("tuple", "pi0"), ("method", "hermite").
  std::vector<std::pair<std::string, std::string>> labels;
  /// Numbers of the report, e.g. patch_degree, max_g1_residual, max_fold_alpha, min_regularity,
  /// interpolation_residual.
  std::vector<std::pair<std::string, double>> measures;
};

/// The patches of an RSD surface and its report: labels construction (rsd), tuple, method;
/// measures patch_degree, triangles, interior_edges, boundary_edges, max_g1_residual,
/// max_fold_alpha, min_regularity, interpolation_residual, max_z (see rsd::RsdReport).
SurfacePatches surface_patches_of(const rsd::RsdSurface& surface);

}  // namespace iga
