#include "assembly/edge_jumps.hpp"

#include <array>
#include <cmath>
#include <stdexcept>

#include "assembly/edge_points.hpp"
#include "assembly/parallel.hpp"

namespace iga {

namespace {

/// Jumps of up to two quantities at point q of a piece, given the unit normal of side a.
using JumpAt = std::array<double, 2> (*)(const FunctionValues& a, const FunctionValues& b, int q, const Eigen::Vector2d& n);

/// Per element, ½ Σ_E Σ_k h_E^powers[k] ‖jump_k‖²_E over the interior edge pieces.
std::vector<double> edge_terms(const Space& space, const Eigen::VectorXd& coefficients, int quadrature_degree,
                               unsigned flags, JumpAt jump_at, std::array<int, 2> powers) {
  if (coefficients.size() != space.dimension())
    throw std::invalid_argument("edge jump terms: one coefficient per basis function expected");
  const std::vector<InteriorEdge> edges = space.interior_edges();
  const QuadratureRule line = gauss_legendre_for_degree(quadrature_degree);
  const int ne = static_cast<int>(edges.size());
  // Point sets of both sides, alive for the whole call: evaluators may cache tables by rule address.
  const EdgeSideRules sides = edge_side_rules(space, edges, line);
  const std::vector<QuadratureRule>& side_a = sides.a;
  const std::vector<QuadratureRule>& side_b = sides.b;
  std::vector<double> piece(ne, 0.0);
#pragma omp parallel if (worth_threads(ne))
  {
    std::unique_ptr<Space::Evaluator> evaluator = space.make_evaluator();
    PointValues geometry_a, geometry_b;
    FunctionValues ua, ub;
#pragma omp for schedule(dynamic, 64)
    for (int k = 0; k < ne; ++k) {
      const InteriorEdge& e = edges[k];
      evaluator->evaluate_function(e.element_a, side_a[k], coefficients, flags, geometry_a, ua);
      evaluator->evaluate_function(e.element_b, side_b[k], coefficients, flags, geometry_b, ub);
      const Point2 tangent = reference_edge_tangent(space.cell_shape(e.element_a), e.edge_a);
      double length = 0.0;
      std::array<double, 2> integral{0.0, 0.0};
      for (int q = 0; q < line.size(); ++q) {
        // Physical tangent of the piece; the normal's orientation does not matter for the squares.
        const Eigen::Vector2d t = geometry_a.jacobian[q] * tangent;
        const double dl = line.weights[q] * t.norm() * std::abs(e.a1 - e.a0);
        const std::array<double, 2> jump = jump_at(ua, ub, q, Eigen::Vector2d(t.y(), -t.x()) / t.norm());
        length += dl;
        for (int j = 0; j < 2; ++j) integral[j] += dl * jump[j] * jump[j];
      }
      for (int j = 0; j < 2; ++j) piece[k] += std::pow(length, powers[j]) * integral[j];
    }
  }
  std::vector<double> out(space.num_elements(), 0.0);
  for (int k = 0; k < ne; ++k) {
    out[edges[k].element_a] += 0.5 * piece[k];
    out[edges[k].element_b] += 0.5 * piece[k];
  }
  return out;
}

}  // namespace

std::vector<double> normal_derivative_jump_terms(const Space& space, const Eigen::VectorXd& coefficients,
                                                 int quadrature_degree) {
  JumpAt jump = [](const FunctionValues& a, const FunctionValues& b, int q, const Eigen::Vector2d& n) {
    return std::array<double, 2>{(a.dx[q] - b.dx[q]) * n.x() + (a.dy[q] - b.dy[q]) * n.y(), 0.0};
  };
  return edge_terms(space, coefficients, quadrature_degree, update_gradients, jump, {1, 0});
}

std::vector<double> laplacian_jump_terms(const Space& space, const Eigen::VectorXd& coefficients,
                                         int quadrature_degree) {
  if (!space.higher_derivatives())
    throw std::invalid_argument("laplacian_jump_terms: the space provides no third derivatives");
  JumpAt jump = [](const FunctionValues& a, const FunctionValues& b, int q, const Eigen::Vector2d& n) {
    const double laplacian = (a.dxx[q] + a.dyy[q]) - (b.dxx[q] + b.dyy[q]);
    const double flux = (a.laplacian_dx[q] - b.laplacian_dx[q]) * n.x() + (a.laplacian_dy[q] - b.laplacian_dy[q]) * n.y();
    return std::array<double, 2>{laplacian, flux};
  };
  return edge_terms(space, coefficients, quadrature_degree, update_hessians | update_laplacian_gradient, jump, {1, 3});
}

}  // namespace iga
