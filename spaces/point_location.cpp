#include "spaces/point_location.hpp"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <deque>
#include <map>
#include <stdexcept>

namespace iga {

namespace {

bool inside_reference(CellShape shape, const Point2& r, double tol) {
  if (shape == CellShape::quadrilateral)
    return r.x() >= -tol && r.y() >= -tol && r.x() <= 1 + tol && r.y() <= 1 + tol;
  return r.x() >= -tol && r.y() >= -tol && r.x() + r.y() <= 1 + tol;
}

Point2 clamp_reference(const Point2& r) {
  return r.cwiseMax(Point2(-0.5, -0.5)).cwiseMin(Point2(1.5, 1.5));
}

}  // namespace

PointLocator::PointLocator(SpacePtr space) : space_(std::move(space)) {
  if (space_->ambient_dimension() != 2) throw std::invalid_argument("points can be located in planar spaces only");
  // Evaluators cache tables by the rule's address: every rule handed to one evaluator stays alive
  // (and so distinct) while it is used.
  const auto evaluator = space_->make_evaluator();
  std::deque<QuadratureRule> rules;
  PointValues pv;
  Eigen::AlignedBox2d all;
  for (int e = 0; e < space_->num_elements(); ++e) {
    QuadratureRule& rule = rules.emplace_back();
    rule.points = space_->sample_cell(e, 6).points;
    rule.weights.assign(rule.points.size(), 0.0);
    evaluator->evaluate_geometry(e, rule, pv);
    Eigen::AlignedBox2d box;
    for (int q = 0; q < pv.num_points(); ++q) box.extend(Point2(pv.x.col(q)));
    // Curved element sides may bulge between the samples.
    const double margin = 0.1 * box.diagonal().norm();
    box.min().array() -= margin;
    box.max().array() += margin;
    boxes_.push_back(box);
    all.extend(box);
  }
  size_ = std::max(1.0, all.diagonal().cwiseAbs().maxCoeff());
}

std::optional<PointLocation> PointLocator::locate(const Point2& x) const {
  const double tol_x = 1e-12 * size_;
  const auto evaluator = space_->make_evaluator();
  std::deque<QuadratureRule> rules;
  PointValues pv;
  const auto map = [&](int e, const Point2& r) {
    QuadratureRule& rule = rules.emplace_back();
    rule.points = {r};
    rule.weights = {0.0};
    evaluator->evaluate_geometry(e, rule, pv);
  };
  for (int e = 0; e < static_cast<int>(boxes_.size()); ++e) {
    if (!boxes_[e].contains(x)) continue;
    const CellShape shape = space_->cell_shape(e);
    const std::vector<Point2> starts =
        shape == CellShape::quadrilateral
            ? std::vector<Point2>{{0.5, 0.5}, {0.2, 0.2}, {0.8, 0.2}, {0.8, 0.8}, {0.2, 0.8}}
            : std::vector<Point2>{{1.0 / 3, 1.0 / 3}, {0.15, 0.15}, {0.7, 0.15}, {0.15, 0.7}};
    for (const Point2& start : starts) {
      Point2 r = start;
      bool converged = false;
      for (int it = 0; it < 30 && !converged; ++it) {
        map(e, r);
        const Point2 residual = Point2(pv.x.col(0)) - x;
        if (residual.norm() <= tol_x) {
          converged = true;
          break;
        }
        const Eigen::Matrix2d& J = pv.jacobian[0];
        if (!(std::abs(J.determinant()) > 0.0)) break;
        const Point2 step = J.lu().solve(residual);
        r = clamp_reference(r - step);
        if (step.norm() <= 1e-14) {
          map(e, r);
          converged = (Point2(pv.x.col(0)) - x).norm() <= 1e-10 * size_;
        }
      }
      if (converged && inside_reference(shape, r, 1e-10)) return PointLocation{e, r};
      if (converged) break;  // the point's preimage lies outside this element
    }
  }
  return std::nullopt;
}

std::vector<PointBasis> PointLocator::basis_at(const std::vector<std::optional<PointLocation>>& where) const {
  std::vector<PointBasis> out(where.size());
  std::map<int, std::vector<std::size_t>> by_element;
  for (std::size_t i = 0; i < where.size(); ++i)
    if (where[i]) by_element[where[i]->element].push_back(i);
  const auto evaluator = space_->make_evaluator();
  std::deque<QuadratureRule> rules;
  PointValues pv;
  for (const auto& [e, indices] : by_element) {
    QuadratureRule& rule = rules.emplace_back();
    for (std::size_t i : indices) rule.points.push_back(where[i]->reference);
    rule.weights.assign(rule.points.size(), 0.0);
    evaluator->evaluate(e, rule, update_values | update_gradients, pv);
    for (std::size_t k = 0; k < indices.size(); ++k) {
      PointBasis& b = out[indices[k]];
      b.dofs = pv.dofs;
      b.value = pv.value.col(static_cast<Eigen::Index>(k));
      b.dx = pv.dx.col(static_cast<Eigen::Index>(k));
      b.dy = pv.dy.col(static_cast<Eigen::Index>(k));
    }
  }
  return out;
}

}  // namespace iga
