#include "spaces/gradient_jump.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <map>
#include <tuple>
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
  // One rule per distinct (shape, edge, parameter range): whole edges share a handful, and
  // evaluators key their tables by a rule's address (a rule per edge piece would build its tables
  // anew every time and grow the evaluator's cache). A deque keeps the addresses stable.
  std::deque<QuadratureRule> rules;
  std::map<std::tuple<int, int, double, double>, const QuadratureRule*> rule_of;
  const auto rule = [&](CellShape shape, int edge, double t0, double t1) {
    const auto key = std::make_tuple(static_cast<int>(shape), edge, t0, t1);
    auto it = rule_of.find(key);
    if (it == rule_of.end()) {
      rules.push_back(side_points(shape, edge, t0, t1, samples));
      it = rule_of.emplace(key, &rules.back()).first;
    }
    return it->second;
  };
  std::vector<const QuadratureRule*> side_a, side_b;
  side_a.reserve(edges.size());
  side_b.reserve(edges.size());
  for (const InteriorEdge& e : edges) {
    side_a.push_back(rule(space.cell_shape(e.element_a), e.edge_a, e.a0, e.a1));
    side_b.push_back(rule(space.cell_shape(e.element_b), e.edge_b, e.b0, e.b1));
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
      evaluator->evaluate_function(edges[k].element_a, *side_a[k], coefficients, update_gradients, geometry, a);
      evaluator->evaluate_function(edges[k].element_b, *side_b[k], coefficients, update_gradients, geometry, b);
      for (int q = 0; q < samples; ++q) {
        const double dx = a.dx(q) - b.dx(q), dy = a.dy(q) - b.dy(q), dz = surface ? a.dz(q) - b.dz(q) : 0.0;
        jump = std::max(jump, std::sqrt(dx * dx + dy * dy + dz * dz));
      }
    }
  }
  return jump;
}

}  // namespace iga
