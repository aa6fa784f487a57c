#pragma once
/// @file
/// Index bookkeeping and evaluation of the tensor Bernstein basis of bidegree (k,k) on the unit
/// square, in the corner and edge conventions of QuadMesh. Coefficient (i,j) (i along u) has local
/// index i + j*(k+1).

#include <Eigen/Core>
#include <vector>

#include "spaces/space.hpp"

namespace iga {

/// Local index of the m-th coefficient (m = 0..k from corner e towards corner e+1) at distance
/// r (0 = on the edge, 1 = next row) from local edge e of the square.
int edge_coefficient(int k, int edge, int m, int r);

/// The 4 local indices of the corner set of corner c ("c00, c10, c01, c11" in its frame).
std::vector<int> corner_coefficients(int k, int corner);

/// Values and first derivatives of all (k+1)^2 tensor Bernstein polynomials at (u,v):
/// row 0 value, row 1 d/du, row 2 d/dv; 3 x (k+1)^2.
Eigen::MatrixXd bernstein_tensor_jet(int k, const Point2& uv);

}  // namespace iga
