#pragma once
/// @file
/// Built-in planar multipatch domains of bilinear quads and affine triangles, and building a
/// PatchMesh from patch corners.

#include <string>
#include <vector>

#include "spaces/g1/patch_mesh.hpp"

namespace iga {

/// The corners of one patch in cyclic order: 4 for a bilinear quad, 3 for a triangle.
using PatchCorners = std::vector<Point2>;

/// A mesh from patches given by their corners in cyclic order. Coincident corners (within 1e-12
/// of the domain size) become one vertex; a patch listed clockwise is reversed to counterclockwise
/// (benchmark files mix both). Validation as in PatchMesh.
PatchMesh mesh_from_patches(const std::vector<PatchCorners>& patches, const std::string& name);

/// Names accepted by multipatch_domain.
std::vector<std::string> multipatch_domain_names();

/// Built-in domains (exact coordinates in shared/notes):
///  - 3p_square: unit square, 3 patches, valence-3 vertex at (0.6, 0.6) (anchors §10);
///  - 5p_square: inner square [0.2,0.8]^2 and 4 trapezoids, four valence-3 vertices (anchors §10);
///  - pentagon: regular pentagon (circumradius 1), 5 patches around the off-centre valence-5
///    vertex (0.07, -0.04) (g1-routeA-evidence);
///  - 5p_pentagon, 3p_hexagon, lshape_8p: G+Smo's regular pentagon (valence 5 at the origin) and
///    hexagon (valence 3, parallelograms), GeoPDEs' 8-patch L-shape (parallelograms) (anchors §10);
///  - 4t_crisscross: unit square, 4 triangles around the centre (T8 of notes §9.1 scaled by 1/2:
///    a crossing vertex);
///  - 4t_star: the same with the centre moved to (0.45, 0.6) (T9 scaled by 1/2: not crossing);
///  - 2q2t_square: unit square, 2 bilinear quads and 2 triangles alternating around (0.55, 0.45)
///    (every interface is triangle–quad; straight-boundary ends at (1, 0.5) and (0, 0.5)).
/// Throws std::invalid_argument for another name.
PatchMesh multipatch_domain(const std::string& name);

}  // namespace iga
