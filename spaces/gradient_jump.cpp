#include "spaces/gradient_jump.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

namespace iga {

namespace {

/// The samples of one side of an edge piece in the element's reference coordinates: parameter
/// t0 + s (t1 - t0) of reference_edge_point, s equispaced in [0, 1].
QuadratureRule side_points(CellShape shape, int edge, double t0, double t1, int samples) {
  QuadratureRule r;
  r.degree = 0;
  for (int k = 0; k < samples; ++k) {
    const double s = double(k) / (samples - 1);
    r.points.push_back(reference_edge_point(shape, edge, t0 + s * (t1 - t0)));
    r.weights.push_back(1.0);
  }
  return r;
}

}  // namespace

double max_gradient_jump(const Space& space, const Eigen::VectorXd& coefficients, int samples) {
  const std::vector<InteriorEdge> edges = space.interior_edges();
  // Every rule stays alive for the whole loop: evaluators may key their tables by a rule's address.
  std::vector<QuadratureRule> side_a, side_b;
  side_a.reserve(edges.size());
  side_b.reserve(edges.size());
  for (const InteriorEdge& e : edges) {
    side_a.push_back(side_points(space.cell_shape(e.element_a), e.edge_a, e.a0, e.a1, samples));
    side_b.push_back(side_points(space.cell_shape(e.element_b), e.edge_b, e.b0, e.b1, samples));
  }
  const bool surface = space.ambient_dimension() == 3;
  double jump = 0.0;
#pragma omp parallel reduction(max : jump) if (edges.size() >= 256)
  {
    const std::unique_ptr<Space::Evaluator> evaluator = space.make_evaluator();
    PointValues geometry;
    FunctionValues a, b;
#pragma omp for schedule(dynamic, 16)
    for (std::size_t k = 0; k < edges.size(); ++k) {
      evaluator->evaluate_function(edges[k].element_a, side_a[k], coefficients, update_gradients, geometry, a);
      evaluator->evaluate_function(edges[k].element_b, side_b[k], coefficients, update_gradients, geometry, b);
      for (int q = 0; q < samples; ++q) {
        const double dx = a.dx(q) - b.dx(q), dy = a.dy(q) - b.dy(q), dz = surface ? a.dz(q) - b.dz(q) : 0.0;
        jump = std::max(jump, std::sqrt(dx * dx + dy * dy + dz * dz));
      }
    }
  }
  return jump;
}

}  // namespace iga
