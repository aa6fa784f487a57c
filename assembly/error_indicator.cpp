#include "assembly/error_indicator.hpp"

#include <Eigen/LU>
#include <cmath>
#include <stdexcept>

#include "assembly/edge_jumps.hpp"
#include "assembly/parallel.hpp"

namespace iga {

namespace {

/// Per element, |K|^power ‖f − L u_h‖²_K, where `flags` asks evaluate_function for what
/// `operator_at(u, q)` = (L u_h)(x_q) reads.
template <class Operator>
std::vector<double> element_residuals(const Space& space, const Eigen::VectorXd& coefficients, const ScalarField& source,
                                      int quadrature_degree, unsigned flags, Operator operator_at, int power) {
  if (coefficients.size() != space.dimension())
    throw std::invalid_argument("residual indicators: one coefficient per basis function expected");
  const int ne = space.num_elements();
  std::vector<double> out(ne, 0.0);
#pragma omp parallel if (worth_threads(ne))
  {
    std::unique_ptr<Space::Evaluator> evaluator = space.make_evaluator();
    PointValues geometry;
    FunctionValues u;
#pragma omp for schedule(dynamic, 16)
    for (int e = 0; e < ne; ++e) {
      const RulePtr rule = space.quadrature(e, quadrature_degree);
      evaluator->evaluate_function(e, *rule, coefficients, flags, geometry, u);
      double area = 0.0, residual2 = 0.0;
      for (int q = 0; q < rule->size(); ++q) {
        const double w = rule->weights[q] * std::abs(geometry.jacobian[q].determinant());
        const double r = source(Point2(geometry.x.col(q))) - operator_at(u, q);
        area += w;
        residual2 += w * r * r;
      }
      out[e] = std::pow(area, power) * residual2;
    }
  }
  return out;
}

/// Per element, Σ over its edges in `edges` of h_E ‖g − Δu_h‖²_E (h_E: the edge's length).
std::vector<double> boundary_laplacian_residuals(const Space& space, const Eigen::VectorXd& coefficients,
                                                 const std::vector<BoundaryEdge>& edges, const BoundaryField& g,
                                                 int quadrature_degree) {
  std::vector<double> out(space.num_elements(), 0.0);
  std::unique_ptr<Space::Evaluator> evaluator = space.make_evaluator();
  PointValues geometry;
  FunctionValues u;
  for (const BoundaryEdge& edge : edges) {
    const RulePtr rule = space.edge_quadrature(edge.element, edge.local_edge, quadrature_degree);
    evaluator->evaluate_function(edge.element, *rule, coefficients, update_gradients | update_hessians, geometry, u);
    const Point2 tangent = reference_edge_tangent(space.cell_shape(edge.element), edge.local_edge);
    double length = 0.0, residual2 = 0.0;
    for (int q = 0; q < rule->size(); ++q) {
      const Eigen::Vector2d t = geometry.jacobian[q] * tangent;
      const double dl = rule->weights[q] * t.norm();
      // Outward normal of a counterclockwise edge.
      const Point2 n = (geometry.jacobian[q].determinant() > 0 ? 1.0 : -1.0) * Point2(t.y(), -t.x()) / t.norm();
      const double r = g(Point2(geometry.x.col(q)), n) - (u.dxx[q] + u.dyy[q]);
      length += dl;
      residual2 += dl * r * r;
    }
    out[edge.element] += length * residual2;
  }
  return out;
}

}  // namespace

namespace {
/// η_K of −Δu + c u = f: h_K² ‖f − (−Δu_h + c u_h)‖²_K (h_K² = |K|) and, for C0 spaces, the jumps.
std::vector<double> second_order_residual_indicators(const Space& space, const Eigen::VectorXd& coefficients,
                                                     const ScalarField& source, double reaction, int quadrature_degree) {
  const unsigned flags = update_gradients | update_hessians | (reaction != 0.0 ? update_values : 0u);
  std::vector<double> eta = element_residuals(
      space, coefficients, source, quadrature_degree, flags,
      [reaction](const FunctionValues& u, int q) {
        return -(u.dxx[q] + u.dyy[q]) + (reaction != 0.0 ? reaction * u.value[q] : 0.0);
      },
      1);
  // The normal-derivative jumps vanish identically in C1 spaces; only C0 spaces pay for them.
  if (space.continuity() == 0) {
    const std::vector<double> jumps = normal_derivative_jump_terms(space, coefficients, quadrature_degree);
    for (std::size_t e = 0; e < eta.size(); ++e) eta[e] += jumps[e];
  }
  for (double& x : eta) x = std::sqrt(x);
  return eta;
}
}  // namespace

std::vector<double> poisson_residual_indicators(const Space& space, const Eigen::VectorXd& coefficients,
                                                const ScalarField& source, int quadrature_degree) {
  return second_order_residual_indicators(space, coefficients, source, 0.0, quadrature_degree);
}

std::vector<double> eigen_residual_indicators(const Space& space, const Eigen::VectorXd& coefficients, double eigenvalue,
                                              int quadrature_degree) {
  // −Δu_h − λ_h u_h against f = 0.
  return second_order_residual_indicators(
      space, coefficients, [](const Point2&) { return 0.0; }, -eigenvalue, quadrature_degree);
}

std::vector<double> plate_residual_indicators(const Space& space, const Eigen::VectorXd& coefficients,
                                              const ScalarField& source, int quadrature_degree,
                                              const std::vector<BoundaryEdge>& simply_supported,
                                              const BoundaryField& laplacian) {
  if (!space.higher_derivatives() || (space.num_elements() > 1 && space.interior_edges().empty()))
    throw std::invalid_argument("plate_residual_indicators: the space needs higher_derivatives() and interior_edges()");
  // h_K⁴ ‖f − Δ²u_h‖², h_K⁴ = |K|².
  std::vector<double> eta = element_residuals(
      space, coefficients, source, quadrature_degree, update_bilaplacian,
      [](const FunctionValues& u, int q) { return u.bilaplacian[q]; }, 2);
  const std::vector<double> jumps = laplacian_jump_terms(space, coefficients, quadrature_degree);
  for (std::size_t e = 0; e < eta.size(); ++e) eta[e] += jumps[e];
  if (!simply_supported.empty()) {
    if (!laplacian) throw std::invalid_argument("plate_residual_indicators: simply supported edges need the data Δu = g_L");
    const std::vector<double> boundary =
        boundary_laplacian_residuals(space, coefficients, simply_supported, laplacian, quadrature_degree);
    for (std::size_t e = 0; e < eta.size(); ++e) eta[e] += boundary[e];
  }
  for (double& x : eta) x = std::sqrt(x);
  return eta;
}

double total_indicator(const std::vector<double>& eta) {
  double s = 0.0;
  for (double x : eta) s += x * x;
  return std::sqrt(s);
}

}  // namespace iga
