#include "solver/study_functionals.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <memory>

namespace iga {

namespace {

std::shared_ptr<QuadratureRule> one_point(const Point2& r) {
  auto rule = std::make_shared<QuadratureRule>();
  rule->points = {r};
  rule->weights = {0.0};
  return rule;
}

bool inside_reference(CellShape shape, const Point2& r, double tol) {
  if (r.x() < -tol || r.y() < -tol) return false;
  return shape == CellShape::quadrilateral ? r.x() <= 1 + tol && r.y() <= 1 + tol : r.x() + r.y() <= 1 + tol;
}

}  // namespace

std::optional<std::pair<int, Point2>> locate_point(const Space& space, const Point2& x) {
  const std::unique_ptr<Space::Evaluator> evaluator = space.make_evaluator();
  // A 5 x 5 sample of each element (kept alive: evaluators may cache tables by rule address).
  QuadratureRule grid;
  for (int j = 0; j <= 4; ++j)
    for (int i = 0; i <= 4; ++i) grid.points.emplace_back(i / 4.0, j / 4.0), grid.weights.push_back(0.0);
  QuadratureRule triangle_grid;
  for (const Point2& p : grid.points)
    if (p.x() + p.y() <= 1.0 + 1e-12) triangle_grid.points.push_back(p), triangle_grid.weights.push_back(0.0);
  std::vector<std::shared_ptr<QuadratureRule>> alive;  // every Newton rule until the search ends
  PointValues geometry;
  const double scale = std::max(space.mesh_size(), 1e-300);
  for (int e = 0; e < space.num_elements(); ++e) {
    const CellShape shape = space.cell_shape(e);
    evaluator->evaluate_geometry(e, shape == CellShape::quadrilateral ? grid : triangle_grid, geometry);
    const Eigen::Vector2d lo = geometry.x.rowwise().minCoeff(), hi = geometry.x.rowwise().maxCoeff();
    const double pad = 0.25 * (hi - lo).maxCoeff();  // curved edges may bulge between samples
    if ((x.array() < lo.array() - pad).any() || (x.array() > hi.array() + pad).any()) continue;
    Point2 r = shape == CellShape::quadrilateral ? Point2(0.5, 0.5) : Point2(1.0 / 3, 1.0 / 3);
    for (int it = 0; it < 30; ++it) {
      alive.push_back(one_point(r));
      evaluator->evaluate_geometry(e, *alive.back(), geometry);
      const Eigen::Vector2d residual = geometry.x.col(0) - x;
      if (residual.norm() <= 1e-12 * scale) {
        if (inside_reference(shape, r, 1e-10)) return std::make_pair(e, r);
        break;
      }
      if (geometry.jacobian.empty()) break;
      r -= geometry.jacobian[0].inverse() * residual;
      if (!r.allFinite()) break;
      // Stay in the reference cell (evaluators may refuse points outside it): a point outside the
      // element then leaves a residual, and the search moves on.
      r = r.cwiseMax(0.0);
      if (shape == CellShape::quadrilateral)
        r = r.cwiseMin(1.0);
      else if (r.sum() > 1.0)
        r /= r.sum();
    }
  }
  return std::nullopt;
}

std::vector<FunctionalSpec> parse_functionals(const ConfigNode& node, const Space& coarse) {
  std::vector<FunctionalSpec> out;
  if (coarse.ambient_dimension() != 2) node.fail("functionals are available for planar problems only");
  for (const std::string& name : node.keys()) {
    const ConfigNode f = node[name];
    // The entries are named by the user, so their keys are checked here rather than declared.
    if (!f.is_map() || f.keys().size() != 1 || (!f.has("point") && !f.has("integral")))
      f.fail("a functional is {point: [x, y]} or {integral: u}");
    FunctionalSpec spec;
    spec.name = name;
    if (name.empty() || name.find_first_of(",\" \t") != std::string::npos)
      f.fail("a functional's name becomes a CSV column: no commas, quotes or spaces");
    if (f.has("point")) {
      spec.kind = FunctionalSpec::Kind::point;
      spec.point = f["point"].as_point();
      if (!locate_point(coarse, spec.point)) f["point"].fail("the point is not in the domain");
    } else {
      if (f["integral"].as_string() != "u") f["integral"].fail("the integral functional is integral: u");
    }
    out.push_back(spec);
  }
  return out;
}

std::vector<double> evaluate_functionals(const std::vector<FunctionalSpec>& functionals, const Space& space,
                                         const Eigen::VectorXd& coefficients) {
  std::vector<double> values;
  const std::unique_ptr<Space::Evaluator> evaluator = space.make_evaluator();
  PointValues geometry;
  FunctionValues uh;
  for (const FunctionalSpec& f : functionals) {
    if (f.kind == FunctionalSpec::Kind::point) {
      const auto at = locate_point(space, f.point);
      if (!at) throw std::runtime_error("functional '" + f.name + "': point not found on this level's mesh");
      const auto rule = one_point(at->second);
      evaluator->evaluate_function(at->first, *rule, coefficients, update_values, geometry, uh);
      values.push_back(uh.value(0));
    } else {
      double sum = 0;
      Eigen::VectorXd jxw;
      for (int e = 0; e < space.num_elements(); ++e) {
        const RulePtr rule = space.quadrature(e, 2 * space.degree() + 2);
        evaluator->evaluate_function(e, *rule, coefficients, update_values, geometry, uh);
        integration_weights(*rule, geometry, jxw);
        sum += jxw.dot(uh.value);
      }
      values.push_back(sum);
    }
  }
  return values;
}

std::optional<double> richardson_order(const std::vector<double>& values, const std::vector<double>& h, std::size_t l) {
  if (l < 2 || l >= values.size() || l >= h.size()) return std::nullopt;
  const double d_prev = std::abs(values[l - 1] - values[l - 2]), d = std::abs(values[l] - values[l - 1]);
  if (!(d_prev > 0) || !(d > 0) || !(h[l - 1] > 0) || !(h[l] > 0) || h[l - 1] == h[l]) return std::nullopt;
  return std::log(d_prev / d) / std::log(h[l - 1] / h[l]);
}

}  // namespace iga
