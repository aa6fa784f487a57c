#pragma once
/// @file
/// VTK's high-order Lagrange cells as the drawing of an element: the reference nodes of
/// VTK_LAGRANGE_QUADRILATERAL / VTK_LAGRANGE_TRIANGLE in VTK's own point order, and the test that
/// decides whether a space's elements are single polynomials such a cell reproduces.

#include <vector>

#include "spaces/space.hpp"

namespace iga {

/// Reference nodes of VTK's Lagrange cell of `order` on the unit square / unit triangle (the
/// reference cells of spaces/space.hpp), in VTK's point order: corners, edge nodes, interior.
std::vector<Point2> lagrange_nodes(CellShape shape, int order);

/// A macro-element's drawing: the reference cell divided uniformly into `divisions`² sub-cells
/// (triangles: the uniform grid's triangles; quadrilaterals: squares), each a Lagrange cell of
/// `order`. Nodes shared by sub-cells appear once in `points`; `cells` lists each sub-cell's
/// nodes in VTK's order.
struct SubdividedLagrange {
  std::vector<Point2> points;
  std::vector<std::vector<int>> cells;
};
SubdividedLagrange subdivided_lagrange(CellShape shape, int order, int divisions);

/// VTK cell type of a Lagrange cell on `shape`.
int lagrange_cell_type(CellShape shape);

/// True when the active functions of the space's elements are polynomials of degree `order` in
/// reference coordinates, so that a Lagrange cell of that order through their values at
/// lagrange_nodes draws them exactly. Tested on up to `max_checked` elements spread over the mesh:
/// each function is interpolated from the nodes and compared at points off the nodal lattice
/// (a macro-element, polynomial only piece by piece, or a non-polynomial basis fails the test).
bool elements_are_polynomial(const Space& space, int order, int max_checked = 64);

}  // namespace iga
