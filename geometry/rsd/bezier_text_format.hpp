#pragma once
/// @file
/// A plain-text file of the Bernstein–Bézier patches of a surface, for other tools:
///
///   # any number of comment lines
///   iga-run-bezier-triangles 1          format name and version
///   degree D                            one degree for all patches
///   patches N
///   patch n i j k                       patch index, then the mesh vertices at t1 = 1, t2 = 1, t3 = 1
///   x y z                               (D+1)(D+2)/2 control points b_α, α = (a1, a2, D − a1 − a2) in the
///   ...                                 order a1 = D, D−1, ..., 0 and, for each a1, a2 = D − a1, ..., 0
///   patch n+1 ...
///
/// The patch is F(t) = Σ b_α D!/(a1! a2! a3!) t1^a1 t2^a2 t3^a3 over barycentrics t of the flat
/// mesh triangle (i, j, k); neighbouring patches share their edge control points. Numbers are
/// written with 17 significant digits, so reading restores them exactly.

#include <array>
#include <istream>
#include <ostream>
#include <string>
#include <vector>

#include "geometry/rsd/bezier_triangle.hpp"
#include "geometry/rsd/rsd_surface.hpp"

namespace iga::rsd {

struct BezierPatchSet {
  std::vector<BezierTriangle> patches;
  std::vector<std::array<int, 3>> vertices;  ///< mesh vertices of each patch
};

/// The patches of `surface` with their mesh vertices.
BezierPatchSet bezier_patches_of(const RsdSurface& surface);

void write_bezier_patches(std::ostream& out, const BezierPatchSet& set, const std::string& comment = "");

/// InputError naming `source` and the line for anything malformed.
BezierPatchSet read_bezier_patches(std::istream& in, const std::string& source);

}  // namespace iga::rsd
