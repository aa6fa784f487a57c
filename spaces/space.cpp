#include "spaces/space.hpp"

#include "config/errors.hpp"
#include "spaces/gradient_jump.hpp"
#include "spaces/surface_values.hpp"

#include <Eigen/LU>  // Matrix2d::determinant
#include <cmath>
#include <stdexcept>

namespace iga {

int num_edges(CellShape shape) { return shape == CellShape::quadrilateral ? 4 : 3; }

Point2 reference_edge_point(CellShape shape, int edge, double t) {
  if (shape == CellShape::quadrilateral) {
    switch (edge) {
      case 0: return {t, 0.0};
      case 1: return {1.0, t};
      case 2: return {1.0 - t, 1.0};
      case 3: return {0.0, 1.0 - t};
    }
  } else {
    switch (edge) {
      case 0: return {t, 0.0};
      case 1: return {1.0 - t, t};
      case 2: return {0.0, 1.0 - t};
    }
  }
  throw std::out_of_range("reference_edge_point: no such edge");
}

Point2 reference_edge_tangent(CellShape shape, int edge) {
  return reference_edge_point(shape, edge, 1.0) - reference_edge_point(shape, edge, 0.0);
}

QuadratureRule edge_rule(CellShape shape, int edge, const QuadratureRule& rule_01) {
  QuadratureRule r;
  r.degree = rule_01.degree;
  r.weights = rule_01.weights;
  r.points.reserve(rule_01.points.size());
  for (const Point2& p : rule_01.points) r.points.push_back(reference_edge_point(shape, edge, p.x()));
  return r;
}

void integration_weights(const QuadratureRule& rule, const PointValues& geometry, Eigen::VectorXd& jxw) {
  const int q = rule.size();
  jxw.resize(q);
  if (!geometry.jacobian3.empty()) {
    for (int k = 0; k < q; ++k) jxw(k) = rule.weights[k] * surface_measure(geometry.jacobian3[k]);
    return;
  }
  for (int k = 0; k < q; ++k) jxw(k) = rule.weights[k] * std::abs(geometry.jacobian[k].determinant());
}

void Space::Evaluator::evaluate_function(int element, const QuadratureRule& points, const Eigen::VectorXd& coefficients,
                                         unsigned flags, PointValues& geometry, FunctionValues& out) {
  space_.element_dofs(element, dofs_);
  element_coefficients_.resize(static_cast<Eigen::Index>(dofs_.size()));
  for (std::size_t i = 0; i < dofs_.size(); ++i) element_coefficients_(static_cast<Eigen::Index>(i)) = coefficients(dofs_[i]);
  evaluate_element_function(element, points, element_coefficients_, flags, geometry, out);
}

std::vector<std::string> Space::boundary_names() const {
  std::vector<std::string> names;
  for (const auto& part : facts_.boundary_parts) names.push_back(part.first);
  return names;
}

std::vector<BoundaryEdge> Space::boundary_edges(const std::string& name) const {
  if (name == "all") return facts_.all_boundary_edges;
  std::string valid = "all";
  for (const auto& [part, edges] : facts_.boundary_parts) {
    if (part == name) return edges;
    valid += ", " + part;
  }
  throw InputError("unknown boundary '" + name + "' of this " + facts_.type + " space (valid: " + valid + ")");
}

std::optional<double> Space::max_gradient_jump(const Eigen::VectorXd& coefficients) const {
  if (facts_.gradient_jump_samples < 2) return std::nullopt;
  return iga::max_gradient_jump(*this, coefficients, facts_.gradient_jump_samples);
}

std::shared_ptr<const Space> Space::refined(const std::vector<int>& marked_elements) const {
  const auto* refinable = dynamic_cast<const LocallyRefinable*>(this);
  return refinable ? refinable->refine(marked_elements) : nullptr;
}

SampleCell Space::sample_cell(int element, int resolution) const {
  SampleCell s;
  const SampleCell& pieces = facts_.pieces;
  if (!pieces.cells.empty()) {
    const int m = resolution / facts_.pieces_across;
    if (m <= 1) return pieces;
    for (const std::vector<int>& t : pieces.cells)
      append_triangle_grid(s, pieces.points[t[0]], pieces.points[t[1]], pieces.points[t[2]], m);
    return s;
  }
  const int m = std::max(1, resolution);
  if (cell_shape(element) == CellShape::quadrilateral) {
    for (int j = 0; j <= m; ++j)
      for (int i = 0; i <= m; ++i) s.points.emplace_back(double(i) / m, double(j) / m);
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i) {
        const int a = j * (m + 1) + i;
        s.cells.push_back({a, a + 1, a + m + 2, a + m + 1});
      }
  } else {
    append_triangle_grid(s, Point2(0, 0), Point2(1, 0), Point2(0, 1), m);
  }
  return s;
}

void append_triangle_grid(SampleCell& cell, const Point2& a, const Point2& b, const Point2& c, int m) {
  // Row j holds m + 1 - j points; index of (i, j) is offset(j) + i.
  std::vector<int> offset(m + 2, static_cast<int>(cell.points.size()));
  for (int j = 0; j <= m; ++j) {
    offset[j + 1] = offset[j] + (m + 1 - j);
    for (int i = 0; i <= m - j; ++i) cell.points.push_back(a + (double(i) / m) * (b - a) + (double(j) / m) * (c - a));
  }
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m - j; ++i) {
      const int p = offset[j] + i, q = p + 1, r = offset[j + 1] + i;
      cell.cells.push_back({p, q, r});
      if (i + 1 < m - j) cell.cells.push_back({q, r + 1, r});
    }
}

}  // namespace iga
