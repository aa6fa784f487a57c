#pragma once
/// @file
/// check_space(space): the properties every space must have, measured (not asserted) so that a
/// test states its own bounds:
///  - partition of unity Σ_i N_i = 1 (largest deviation; holds for Bernstein, B-spline, T-mesh and
///    WS4 bases, not for every G1 basis);
///  - first derivatives against central differences of values along the element map
///    (Jᵀ∇N = ∂N̂/∂ξ), second derivatives against central differences of gradients
///    (∇²N J = ∂∇N/∂ξ in the plane; on surfaces the covariant Hessian, H J = P ∂∇_ΓN/∂ξ);
///  - jumps of values and of gradients across interior edges (Space::interior_edges());
///  - quadrature exactness of quadrature(e, d) on the monomials ξ^a η^b of degree ≤ d;
///  - Evaluator::evaluate_function (each evaluator contracts the coefficients its own way) against the
///    contraction of evaluate's arrays with the same coefficients: values, gradients, Hessians;
///  - evaluator vs extraction: a space with an evaluator specialisation (FastEvaluator,
///    spaces/element_core.hpp) against the generic evaluator on its explicit core, every array of
///    evaluate, evaluate_function, evaluate_geometry and integrate_values.
/// Derivative errors are relative, |error| / (|reference| + 1) per function; with step h a
/// central difference errs by O(h²) (truncation) + O(ε/h) (round-off); both h and h/2 are measured,
/// so that a test can ask for the factor 4 of a consistent derivative instead of a bound that
/// depends on the size of the third derivatives.

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross
#include <algorithm>
#include <cmath>
#include <vector>

#include "spaces/element_core.hpp"
#include "spaces/space.hpp"

namespace iga::test {

struct SpaceCheck {
  double partition_of_unity = 0;  ///< max |Σ_i N_i − 1| at the sampled points
  double gradient_fd = 0;         ///< max relative |Jᵀ∇N − FD of N| with step h
  double hessian_fd = 0;          ///< max relative |H J − P FD of ∇N| with step h
  double gradient_fd_half = 0;    ///< the same with step h/2: ≈ gradient_fd / 4 unless at round-off
  double hessian_fd_half = 0;     ///< the same with step h/2
  double value_jump = 0;          ///< max |[N_i]| over interior edges, relative to max |N_i|
  double gradient_jump = 0;       ///< max |[∇N_i]| over interior edges, relative to max |∇N_i|
  int edges_checked = 0;
  double function_values = 0;     ///< max |evaluate_function − Σ c_i (evaluate)| / (|Σ|c_i| ...| + 1)
  double quadrature = 0;          ///< max |Q(ξ^a η^b) − ∫ ξ^a η^b| over degrees ≤ 2p
  /// FastEvaluator spaces: max |fast − generic| / (max |generic| + 1) per array; -1: no fast kernel.
  double evaluator_vs_extraction = -1;
};

namespace detail {

inline QuadratureRule points_rule(const std::vector<Point2>& points) {
  QuadratureRule r;
  r.points = points;
  r.weights.assign(points.size(), 1.0);
  return r;
}

/// Largest |a − b| / (max |b| + 1) (arrays of the same shape; empty arrays agree).
inline double relative_difference(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  if (a.size() == 0 && b.size() == 0) return 0.0;
  if (a.rows() != b.rows() || a.cols() != b.cols()) return 1e300;
  return (a - b).cwiseAbs().maxCoeff() / (b.cwiseAbs().maxCoeff() + 1);
}

/// The fast evaluator `fast` against `generic` on element e at the rule: every array of evaluate,
/// of evaluate_function (coefficients c), the points of evaluate_geometry and integrate_values.
inline double compare_evaluators(Space::Evaluator& fast, Space::Evaluator& generic, int e, const QuadratureRule& rule,
                                 const Eigen::VectorXd& c) {
  const unsigned all = update_values | update_gradients | update_hessians;
  double worst = 0;
  PointValues a, b;
  fast.evaluate(e, rule, all, a);
  generic.evaluate(e, rule, all, b);
  if (a.dofs != b.dofs) return 1e300;
  for (auto m : {&PointValues::value, &PointValues::dx, &PointValues::dy, &PointValues::dz, &PointValues::dxx,
                 &PointValues::dxy, &PointValues::dyy, &PointValues::dxz, &PointValues::dyz, &PointValues::dzz})
    worst = std::max(worst, relative_difference(a.*m, b.*m));
  worst = std::max(worst, relative_difference(a.x, b.x));
  FunctionValues fa, fb;
  fast.evaluate_function(e, rule, c, all, a, fa);
  generic.evaluate_function(e, rule, c, all, b, fb);
  for (auto m : {&FunctionValues::value, &FunctionValues::dx, &FunctionValues::dy, &FunctionValues::dz,
                 &FunctionValues::dxx, &FunctionValues::dxy, &FunctionValues::dyy, &FunctionValues::dzz})
    worst = std::max(worst, relative_difference(fa.*m, fb.*m));
  fast.evaluate_geometry(e, rule, a);
  generic.evaluate_geometry(e, rule, b);
  worst = std::max(worst, relative_difference(a.x, b.x));
  Eigen::VectorXd la, lb;
  const Eigen::VectorXd w = Eigen::VectorXd::LinSpaced(rule.size(), 1.0, 2.0);
  fast.integrate_values(e, rule, a, w, la);
  generic.integrate_values(e, rule, b, w, lb);
  return std::max(worst, relative_difference(la, lb));
}

/// The 3×2 Jacobian of point k in ambient coordinates (planar: z row zero).
inline Eigen::Matrix<double, 3, 2> jacobian3(const PointValues& pv, int k) {
  if (!pv.jacobian3.empty()) return pv.jacobian3[k];
  Eigen::Matrix<double, 3, 2> J = Eigen::Matrix<double, 3, 2>::Zero();
  J.topRows(2) = pv.jacobian[k];
  return J;
}

inline double factorial(int n) { return n <= 1 ? 1.0 : n * factorial(n - 1); }

}  // namespace detail

/// Measure the properties on every `stride`-th element (at three interior points each) and on
/// every `stride`-th interior edge, with finite-difference step h in reference coordinates.
inline SpaceCheck check_space(const Space& space, int stride = 1, double h = 1e-4) {
  SpaceCheck out;
  auto ev = space.make_evaluator();
  const auto* fast = dynamic_cast<const FastEvaluator*>(&space);
  std::unique_ptr<Space::Evaluator> generic = fast ? fast->make_generic_evaluator() : nullptr;
  if (generic) out.evaluator_vs_extraction = 0;
  const unsigned all = update_values | update_gradients | update_hessians;
  for (int e = 0; e < space.num_elements(); e += stride) {
    const bool tri = space.cell_shape(e) == CellShape::triangle;
    const std::vector<Point2> interior =
        tri ? std::vector<Point2>{{0.21, 0.33}, {0.58, 0.27}, {0.13, 0.71}}
            : std::vector<Point2>{{0.21, 0.33}, {0.71, 0.62}, {0.38, 0.87}};
    for (const double step : {h, h / 2})
      for (const Point2& r : interior) {
        const QuadratureRule rule = detail::points_rule(
            {r, r + Point2(step, 0), r - Point2(step, 0), r + Point2(0, step), r - Point2(0, step)});
        PointValues pv;
        ev->evaluate(e, rule, all, pv);
        const Eigen::Matrix<double, 3, 2> J = detail::jacobian3(pv, 0);
        Eigen::Matrix3d P = Eigen::Matrix3d::Identity();
        if (!pv.jacobian3.empty()) {
          const Eigen::Vector3d n = J.col(0).cross(J.col(1)).normalized();
          P -= n * n.transpose();
        }
        out.partition_of_unity = std::max(out.partition_of_unity, std::abs(pv.value.col(0).sum() - 1.0));
        double& grad_fd = step == h ? out.gradient_fd : out.gradient_fd_half;
        double& hess_fd = step == h ? out.hessian_fd : out.hessian_fd_half;
        for (int i = 0; i < pv.num_functions(); ++i) {
          const Eigen::Vector3d g = pv.gradient(i, 0);
          const Eigen::Vector2d dv((pv.value(i, 1) - pv.value(i, 2)) / (2 * step),
                                   (pv.value(i, 3) - pv.value(i, 4)) / (2 * step));
          grad_fd = std::max(grad_fd, (J.transpose() * g - dv).norm() / ((J.transpose() * g).norm() + 1));
          Eigen::Matrix<double, 3, 2> dg;
          dg.col(0) = (pv.gradient(i, 1) - pv.gradient(i, 2)) / (2 * step);
          dg.col(1) = (pv.gradient(i, 3) - pv.gradient(i, 4)) / (2 * step);
          const Eigen::Matrix<double, 3, 2> HJ = pv.hessian(i, 0) * J;
          hess_fd = std::max(hess_fd, (HJ - P * dg).norm() / (HJ.norm() + 1));
        }
      }
    // evaluate_function against Σ c_i N_i with coefficients c_i = sin(i + 1) (fixed, all sizes).
    {
      const RulePtr rule = space.quadrature(e, space.degree());
      Eigen::VectorXd c(space.dimension());
      for (int i = 0; i < c.size(); ++i) c(i) = std::sin(i + 1.0);
      PointValues pv, geometry;
      FunctionValues fv;
      ev->evaluate(e, *rule, all, pv);
      ev->evaluate_function(e, *rule, c, all, geometry, fv);
      Eigen::VectorXd local(pv.num_functions());
      for (int i = 0; i < pv.num_functions(); ++i) local(i) = c(pv.dofs[i]);
      const bool surface = pv.dzz.size() > 0;
      const std::vector<std::pair<const Eigen::MatrixXd*, const Eigen::VectorXd*>> arrays = {
          {&pv.value, &fv.value}, {&pv.dx, &fv.dx},   {&pv.dy, &fv.dy},   {&pv.dxx, &fv.dxx},
          {&pv.dxy, &fv.dxy},     {&pv.dyy, &fv.dyy}};
      auto compare = [&](const Eigen::MatrixXd& table, const Eigen::VectorXd& got) {
        const Eigen::VectorXd want = table.transpose() * local;
        const double scale = (table.cwiseAbs().transpose() * local.cwiseAbs()).maxCoeff() + 1;
        out.function_values = std::max(out.function_values, (want - got).cwiseAbs().maxCoeff() / scale);
      };
      for (const auto& [table, got] : arrays) compare(*table, *got);
      if (surface) {
        compare(pv.dz, fv.dz);
        compare(pv.dxz, fv.dxz);
        compare(pv.dyz, fv.dyz);
        compare(pv.dzz, fv.dzz);
      }
      if (generic)
        out.evaluator_vs_extraction =
            std::max(out.evaluator_vs_extraction, detail::compare_evaluators(*ev, *generic, e, *rule, c));
    }
    // Quadrature: monomials of the reference coordinates up to degree 2p (per direction on squares).
    const int d = 2 * space.degree();
    const RulePtr rule = space.quadrature(e, d);
    for (int a = 0; a <= d; ++a)
      for (int b = 0; b <= (tri ? d - a : d); ++b) {
        double sum = 0;
        for (int k = 0; k < rule->size(); ++k)
          sum += rule->weights[k] * std::pow(rule->points[k].x(), a) * std::pow(rule->points[k].y(), b);
        const double exact = tri ? detail::factorial(a) * detail::factorial(b) / detail::factorial(a + b + 2)
                                 : 1.0 / ((a + 1) * (b + 1));
        out.quadrature = std::max(out.quadrature, std::abs(sum - exact));
      }
  }
  // Jumps across interior edges: every global function active on either side, at 7 points.
  const std::vector<InteriorEdge> edges = space.interior_edges();
  for (std::size_t j = 0; j < edges.size(); j += stride) {
    const InteriorEdge& ie = edges[j];
    std::vector<Point2> pa, pb;
    for (int s = 0; s < 7; ++s) {
      const double t = (s + 0.5) / 7;
      pa.push_back(reference_edge_point(space.cell_shape(ie.element_a), ie.edge_a, ie.a0 + t * (ie.a1 - ie.a0)));
      pb.push_back(reference_edge_point(space.cell_shape(ie.element_b), ie.edge_b, ie.b0 + t * (ie.b1 - ie.b0)));
    }
    PointValues va, vb;
    ev->evaluate(ie.element_a, detail::points_rule(pa), update_values | update_gradients, va);
    ev->evaluate(ie.element_b, detail::points_rule(pb), update_values | update_gradients, vb);
    std::vector<int> global = va.dofs;
    global.insert(global.end(), vb.dofs.begin(), vb.dofs.end());
    std::sort(global.begin(), global.end());
    global.erase(std::unique(global.begin(), global.end()), global.end());
    double vmax = 0, gmax = 0, vjump = 0, gjump = 0;
    for (int dof : global) {
      const auto ia = std::find(va.dofs.begin(), va.dofs.end(), dof) - va.dofs.begin();
      const auto ib = std::find(vb.dofs.begin(), vb.dofs.end(), dof) - vb.dofs.begin();
      const bool on_a = ia < static_cast<long>(va.dofs.size()), on_b = ib < static_cast<long>(vb.dofs.size());
      for (int k = 0; k < 7; ++k) {
        const double a = on_a ? va.value(ia, k) : 0.0, b = on_b ? vb.value(ib, k) : 0.0;
        const Eigen::Vector3d ga = on_a ? va.gradient(static_cast<int>(ia), k) : Eigen::Vector3d::Zero();
        const Eigen::Vector3d gb = on_b ? vb.gradient(static_cast<int>(ib), k) : Eigen::Vector3d::Zero();
        vmax = std::max({vmax, std::abs(a), std::abs(b)});
        gmax = std::max({gmax, ga.norm(), gb.norm()});
        vjump = std::max(vjump, std::abs(a - b));
        gjump = std::max(gjump, (ga - gb).norm());
      }
    }
    out.value_jump = std::max(out.value_jump, vjump / vmax);
    out.gradient_jump = std::max(out.gradient_jump, gjump / gmax);
    ++out.edges_checked;
  }
  return out;
}

}  // namespace iga::test
