#pragma once
/// @file
/// The Bernstein–Bézier control points of a surface's patches as plain text, for other tools
/// (format in docs/spaces/surface.md, "Surface files"):
///
///   # any number of comment lines (and blank lines)
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

#include <istream>
#include <ostream>
#include <string>

#include "geometry/surface_patches.hpp"

namespace iga {

/// Writes the patches and vertices of `surface` (not its report) with `comment` as first line.
void write_bernstein_patches(std::ostream& out, const SurfacePatches& surface, const std::string& comment = "");

/// Writes `filename`; std::runtime_error if it cannot be written.
void write_bernstein_patches_file(const SurfacePatches& surface, const std::string& filename,
                                  const std::string& comment = "");

/// Reads patches and vertices back (labels and measures stay empty). InputError naming `source`
/// and the line for anything malformed.
SurfacePatches read_bernstein_patches(std::istream& in, const std::string& source);

}  // namespace iga
