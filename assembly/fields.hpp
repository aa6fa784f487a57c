#pragma once
/// @file
/// Functions the assembly layer integrates against. They are plain callables so that the
/// assembler does not depend on how a function was given (symbolic expression, closure, ...).
/// They must be safe to call from several threads at once.

#include <functional>

#include "quadrature/quadrature_rule.hpp"

namespace iga {

/// f(x): a source term or a component of an exact solution.
using ScalarField = std::function<double(const Point2& x)>;
/// g(x, n): boundary data that may depend on the outward unit normal n (e.g. du/dn = grad u . n).
using BoundaryField = std::function<double(const Point2& x, const Point2& n)>;

/// An exact solution and its derivatives; members left empty are not available.
struct ExactSolution {
  ScalarField u, ux, uy, uxx, uxy, uyy;
  bool has_gradient() const { return ux && uy; }
  bool has_hessian() const { return uxx && uxy && uyy; }
};

}  // namespace iga
