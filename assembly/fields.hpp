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
/// Several fields at the q points of an element at once: values(i, k) = f_i(points.col(k)),
/// values resized to (number of fields) x q. Loops over quadrature points prefer it to a
/// ScalarField per point (one compiled program for all points and all fields).
using BatchField = std::function<void(const Eigen::Matrix2Xd& points, Eigen::MatrixXd& values)>;
/// g(x, n): boundary data that may depend on the outward unit normal n (e.g. du/dn = grad u . n).
using BoundaryField = std::function<double(const Point2& x, const Point2& n)>;

/// f(x) at a point of a surface in 3D.
using SurfaceField = std::function<double(const Eigen::Vector3d& x)>;
/// f(x, n, H) on a surface in 3D: data that depend on the surface's unit normal n and mean
/// curvature H = div_Γ n at x (e.g. f = −Δ_Γ u + u computed from u given in x, y, z).
using SurfaceSource = std::function<double(const Eigen::Vector3d& x, const Eigen::Vector3d& n, double H)>;

/// An exact solution on a surface in 3D, given in ambient coordinates: u, its ambient gradient
/// (the error norms project it onto the tangent plane) and optionally its ambient Hessian (the
/// surface H2 seminorm turns it into the covariant Hessian: assembly/surface_calculus.hpp).
struct SurfaceExactSolution {
  SurfaceField u, ux, uy, uz;
  SurfaceField uxx, uxy, uxz, uyy, uyz, uzz;
  bool has_gradient() const { return ux && uy && uz; }
  bool has_hessian() const { return uxx && uxy && uxz && uyy && uyz && uzz; }
};

/// An exact solution and its derivatives; members left empty are not available.
struct ExactSolution {
  ScalarField u, ux, uy, uxx, uxy, uyy;
  /// Optional: the same six functions (rows u, ux, uy, uxx, uxy, uyy) in one batch, which the
  /// error norms use when it is set; rows of members left empty above are not read.
  BatchField jet;
  bool has_gradient() const { return ux && uy; }
  bool has_hessian() const { return uxx && uxy && uyy; }
};

}  // namespace iga
