#pragma once
/// @file
/// Exact extraction of a WS4 element (notes §8.2–8.3): C_K = A⁻¹ T_K, where T_K expresses the
/// paper's 51 affine-invariant functionals ρ_j (directional derivatives along the element's edge
/// vectors at its corners, derivatives towards the opposite corner at the edge points, interior
/// values) through the element's global DOFs g (Cartesian-frame vertex derivatives, normal
/// derivatives along globally oriented edges, interior values): ρ = T_K g. T_K is assembled from
/// the corners alone (chain rule for the vertex rows; for the edge rows the 1D trace maps of
/// ws4_edge_traces.hpp), in long double, and A⁻¹ is exact (ws4_collocation.hpp), so no 51 x 51
/// system is solved per element: C_K is exact up to the rounding of its factors and of one product.

#include <Eigen/Core>
#include <array>

#include "quadrature/quadrature_rule.hpp"
#include "spaces/ws4/ws4_collocation.hpp"

namespace iga::ws4 {

/// What the extraction of one element needs to know about its corners and global DOFs. Local edge e
/// runs from corner e to corner (e + 1) % 3; DOF order as in ws4_dof_layout.hpp.
struct ElementDofGeometry {
  std::array<Point2, 3> corner;          ///< physical P0, P1, P2 (counterclockwise or not)
  std::array<Eigen::Matrix2d, 3> frame;  ///< vertex frame (d1, d2) of each corner, as columns
  std::array<double, 3> vertex_scale;    ///< a vertex DOF of order k is vertex_scale^k × the derivative
  std::array<bool, 3> edge_reversed;     ///< the global orientation of local edge e is P_{e+1} → P_e
  std::array<double, 3> edge_scale;      ///< an edge DOF of order k is edge_scale^k × ∂_n^k u
};

/// T_K (51 x 51): row j gives ρ_{j+1} as a combination of the element's 51 DOFs.
Matrix51L ws4_functionals_from_dofs(const ElementDofGeometry& geometry);

/// C_K = A⁻¹ T_K (51 x 51): column m holds the B-coefficients of the shape function of DOF m.
Eigen::MatrixXd ws4_exact_extraction(const ElementDofGeometry& geometry);

}  // namespace iga::ws4
