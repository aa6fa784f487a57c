#pragma once
/// @file
/// Index bookkeeping and evaluation of the Bernstein basis of one face of a PatchMesh (notes §1.2):
/// bidegree (k,k) on the unit square, total degree k on the unit triangle, in the corner and edge
/// conventions of PatchMesh.
///
/// Local indices: square, coefficient (i,j) (i along u) is i + j*(k+1); triangle, b_{i,j} =
/// k!/(i!j!l!) u^i v^j w^l (w = 1-u-v, l = k-i-j) is j*(k+1) - j*(j-1)/2 + i. Triangle corner c
/// has barycentric coordinate λ_c with λ_0 = w, λ_1 = u, λ_2 = v.

#include <Eigen/Core>
#include <vector>

#include "spaces/space.hpp"

namespace iga {

/// Local index of the triangle's b_{i,j} = k!/(i!j!l!) u^i v^j w^l (exponents i of u, j of v).
inline int bernstein_triangle_index(int k, int i, int j) { return j * (k + 1) - j * (j - 1) / 2 + i; }

/// Number of Bernstein polynomials: (k+1)^2 or (k+1)(k+2)/2.
int bernstein_count(CellShape shape, int k);

/// Index of the last coefficient of row r (0 or 1) along an edge: k on a square, k - r on a
/// triangle (a triangle's next row is one shorter).
int edge_row_last(CellShape shape, int k, int r);

/// Local index of the m-th coefficient (m = 0..edge_row_last(r), from corner e towards corner
/// e+1) at distance r (0 = on the edge, 1 = next row) from local edge e.
int edge_coefficient(CellShape shape, int k, int edge, int m, int r);

/// The 4 local indices of the corner set of corner c ("c00, c10, c01, c11" in its frame, c10
/// along edge c).
std::vector<int> corner_coefficients(CellShape shape, int k, int corner);

/// Local indices of the coefficients at distance >= 2 from every edge (the face functions).
std::vector<int> interior_coefficients(CellShape shape, int k);

/// Values and first derivatives of all Bernstein polynomials at (u,v): row 0 value, row 1 d/du,
/// row 2 d/dv; 3 x bernstein_count.
Eigen::MatrixXd bernstein_jet(CellShape shape, int k, const Point2& uv);

/// Tables at the points of a rule, bernstein_count x q each: value, d/du, d/dv, d2/du2, d2/dudv,
/// d2/dv2.
void bernstein_tables(CellShape shape, int k, const std::vector<Point2>& points, Eigen::MatrixXd (&tables)[6]);

}  // namespace iga
