#pragma once
/// @file
/// The coefficient vector k of the constant function 1 in a space: Σ_i k_i N_i = 1. It is all
/// ones only for a basis that is a partition of unity (B-splines, Bernstein triangles); the
/// 4-split G1 basis is not one (its vertex functions carry derivative data), so whatever removes
/// or pins the constants of a kernel (ConstantKernel) must use k, not a vector of ones.

#include <Eigen/Core>

#include "spaces/space.hpp"

namespace iga {

/// k with Σ_i k_i N_i = 1 on every element. All ones when the basis sums to 1 at the points of
/// every element (checked); else fitted element by element: the functions not yet known on an
/// element are fitted to 1 − (the known ones) at the points of a rule of degree 2p + 2 by least
/// squares, and taken where they are linearly independent there (then the fit is exact and unique).
/// Throws std::runtime_error if some function stays unknown or the result misses 1 by more than
/// 1e-9 at some point (the constants are not in the space).
Eigen::VectorXd constant_coefficients(const Space& space);

}  // namespace iga
