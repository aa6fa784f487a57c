#pragma once
/// @file
/// The local basis of a tensor-product element: Bernstein polynomials of degrees (pu, pv) on the
/// unit square, tabulated with their derivatives to second order, the element's extraction and the
/// boundary of the element grid. Shared by the planar B-spline space and the B-splines on NURBS
/// patches in 3D (the same local basis under another map).

#include <vector>

#include "spaces/element_core.hpp"

namespace iga {

/// Fills `tables` (value, ∂ξ, ∂η, ∂ξξ, ∂ξη, ∂ηη; (pu + 1)(pv + 1) × points each, ξ index fastest)
/// and returns the derivative order it computed (2).
int tabulate_tensor_bernstein(int pu, int pv, const std::vector<Point2>& points, LocalTables& tables);

/// C_e = C_v ⊗ C_u of the element with 1D extractions cu, cv (active × local each), stored
/// transposed: local × active, column-major, compressed (extraction_view reads it as C_e); local
/// index l + m (cu.cols()), active a + b (cu.rows()).
Eigen::SparseMatrix<double> tensor_extraction(const Eigen::MatrixXd& cu, const Eigen::MatrixXd& cv);

/// The sides of an nex × ney element grid (element ex + ey nex) into `facts`: all_boundary_edges
/// bottom, right, top, left (edges 0..3 of the elements), and the parts left, right (when `open_u`),
/// bottom, top (when `open_v`); a closed (periodic) direction has no sides.
void add_grid_boundary(SpaceFacts& facts, int nex, int ney, bool open_u, bool open_v);

}  // namespace iga
