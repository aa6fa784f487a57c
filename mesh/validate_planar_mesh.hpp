#pragma once
/// @file
/// Checks a PlanarMesh before a space is built on it. Every failure is an InputError that names
/// the mesh source and the offending cell (with its corner coordinates), edge or vertex.

#include <string>

#include "mesh/planar_mesh.hpp"

namespace iga {

/// Which cells a space accepts; `space` names it in messages ("the ws4 space needs triangles").
struct AllowedCells {
  bool triangles = true;
  bool quads = true;
  std::string space;
};

/// Relative tolerance of the geometric checks: a cell is degenerate when its area is at most
/// tolerance x (its longest edge)², a quad corner folded when the corner's cross product is at most
/// tolerance x (its longest edge)², and two vertices coincide when closer than tolerance x (mesh
/// diameter).
inline constexpr double mesh_tolerance = 1e-10;

/// Shape tolerance: a valid cell is still refused when a corner's cross product is below
/// mesh_shape_tolerance x (its longest edge)² — for a triangle twice its area over h², for a
/// rectangle a x b its aspect ratio a / b. Thinner cells (aspect ratios above 100, vertices closer
/// than a hundredth of the cell) made the G1 and WS4 spaces singular in floating point. Relative,
/// so independent of the mesh's scale.
inline constexpr double mesh_shape_tolerance = 1e-2;

/// Rejects, in this order: a cell that is not a triangle or quadrilateral, or one not allowed;
/// a vertex id out of range or repeated in a cell; a degenerate cell (area <= tol h²); a clockwise
/// cell; a folded or non-convex quad (bilinear map Jacobian <= 0 at a corner); two coincident
/// vertices; an edge of more than two cells (non-manifold); two cells traversing an edge in the
/// same direction (they overlap: the mesh folds over itself); a vertex where the boundary touches
/// itself (more than two boundary edges); an unreferenced vertex; a boundary group edge that is not
/// a boundary edge of the mesh; a boundary group name that is not UTF-8; a nearly degenerate cell
/// (a corner below mesh_shape_tolerance).
void validate_planar_mesh(const PlanarMesh& mesh, const AllowedCells& allowed = {});

}  // namespace iga
