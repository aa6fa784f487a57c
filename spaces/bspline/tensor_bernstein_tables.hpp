#pragma once
/// @file
/// The local basis of a tensor-product element: Bernstein polynomials of degrees (pu, pv) on the
/// unit square, tabulated with their derivatives to second order. Shared by the planar B-spline
/// space and the B-splines on NURBS patches in 3D (the same local basis under another map).

#include <vector>

#include "spaces/element_core.hpp"

namespace iga {

/// Fills `tables` (value, ∂ξ, ∂η, ∂ξξ, ∂ξη, ∂ηη; (pu + 1)(pv + 1) × points each, ξ index fastest)
/// and returns the derivative order it computed (2).
int tabulate_tensor_bernstein(int pu, int pv, const std::vector<Point2>& points, LocalTables& tables);

}  // namespace iga
