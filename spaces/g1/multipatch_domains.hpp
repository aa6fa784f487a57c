#pragma once
/// @file
/// Built-in planar multipatch domains of bilinear quads, and building a QuadMesh from patch corners.

#include <array>
#include <string>
#include <vector>

#include "spaces/g1/quad_mesh.hpp"

namespace iga {

/// A mesh from patches given by their 4 corners in cyclic order. Coincident corners (within 1e-12
/// of the domain size) become one vertex; a patch listed clockwise is reversed to counterclockwise
/// (benchmark files mix both). Validation as in QuadMesh.
QuadMesh mesh_from_patches(const std::vector<std::array<Point2, 4>>& patches, const std::string& name);

/// Names accepted by multipatch_domain.
std::vector<std::string> multipatch_domain_names();

/// Built-in domains (exact coordinates in shared/notes):
///  - 3p_square: unit square, 3 patches, valence-3 vertex at (0.6, 0.6) (anchors §10);
///  - 5p_square: inner square [0.2,0.8]^2 and 4 trapezoids, four valence-3 vertices (anchors §10);
///  - pentagon: regular pentagon (circumradius 1), 5 patches around the off-centre valence-5
///    vertex (0.07, -0.04) (g1-routeA-evidence);
///  - 5p_pentagon, 3p_hexagon, lshape_8p: G+Smo's regular pentagon (valence 5 at the origin) and
///    hexagon (valence 3, parallelograms), GeoPDEs' 8-patch L-shape (parallelograms) (anchors §10).
/// Throws std::invalid_argument for another name.
QuadMesh multipatch_domain(const std::string& name);

}  // namespace iga
