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

/// Newton iterates stay in the reference cell (evaluators of macro-elements find the polynomial
/// piece of a point and may refuse points outside): a point outside the element then keeps a
/// residual, and is reported as not inside.
Point2 clamp_to_cell(CellShape shape, Point2 r) {
  r = r.cwiseMax(0.0);
  if (shape == CellShape::quadrilateral) return r.cwiseMin(1.0);
  if (r.sum() > 1.0) r /= r.sum();
  return r;
}

}  // namespace

QuadratureRule reference_samples(CellShape shape) {
  QuadratureRule out;
  for (int j = 0; j <= 4; ++j)
    for (int i = 0; i <= 4; ++i)
      if (shape == CellShape::quadrilateral || i + j <= 4) out.points.emplace_back(i / 4.0, j / 4.0);
  out.weights.assign(out.points.size(), 0.0);
  return out;
}

PointLocator::PointLocator(SpacePtr space) : space_(std::move(space)) {
  if (space_->ambient_dimension() != 2) throw std::invalid_argument("points can be located in planar spaces only");
  const auto evaluator = space_->make_evaluator();
  // A 5 x 5 sample of each element (its triangle part for triangles): two rules for all elements.
  const QuadratureRule square = reference_samples(CellShape::quadrilateral);
  const QuadratureRule triangle = reference_samples(CellShape::triangle);
  PointValues pv;
  for (int e = 0; e < space_->num_elements(); ++e) {
    evaluator->evaluate_geometry(e, space_->cell_shape(e) == CellShape::quadrilateral ? square : triangle, pv);
    Eigen::AlignedBox2d box;
    for (int q = 0; q < pv.num_points(); ++q) box.extend(Point2(pv.x.col(q)));
    // Curved element sides may bulge between the samples.
    const double margin = 0.15 * box.diagonal().norm();
    box.min().array() -= margin;
    box.max().array() += margin;
    boxes_.push_back(box);
    all_.extend(box);
  }
  size_ = std::max(1.0, all_.diagonal().cwiseAbs().maxCoeff());
  // About one bin per element, square bins: a query looks at the few boxes of its bin only.
  const Point2 extent = all_.diagonal().cwiseMax(1e-300);
  const double n = std::max(1, space_->num_elements());
  const double bin = std::sqrt(extent.x() * extent.y() / n);
  bins_x_ = std::clamp(static_cast<int>(std::ceil(extent.x() / bin)), 1, 4096);
  bins_y_ = std::clamp(static_cast<int>(std::ceil(extent.y() / bin)), 1, 4096);
  bins_.assign(static_cast<std::size_t>(bins_x_) * bins_y_, {});
  const auto bin_of = [&](double v, double lo, double width, int count) {
    return std::clamp(static_cast<int>((v - lo) / width * count), 0, count - 1);
  };
  for (int e = 0; e < static_cast<int>(boxes_.size()); ++e) {
    const int i0 = bin_of(boxes_[e].min().x(), all_.min().x(), extent.x(), bins_x_);
    const int i1 = bin_of(boxes_[e].max().x(), all_.min().x(), extent.x(), bins_x_);
    const int j0 = bin_of(boxes_[e].min().y(), all_.min().y(), extent.y(), bins_y_);
    const int j1 = bin_of(boxes_[e].max().y(), all_.min().y(), extent.y(), bins_y_);
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) bins_[static_cast<std::size_t>(j) * bins_x_ + i].push_back(e);
  }
}

void PointLocator::candidates(const Point2& x, std::vector<int>& out) const {
  out.clear();
  if (!all_.contains(x)) return;
  const Point2 extent = all_.diagonal().cwiseMax(1e-300);
  const int i = std::clamp(static_cast<int>((x.x() - all_.min().x()) / extent.x() * bins_x_), 0, bins_x_ - 1);
  const int j = std::clamp(static_cast<int>((x.y() - all_.min().y()) / extent.y() * bins_y_), 0, bins_y_ - 1);
  for (int e : bins_[static_cast<std::size_t>(j) * bins_x_ + i])
    if (boxes_[e].contains(x)) out.push_back(e);
}

void PointLocator::invert_map(int element, const Eigen::Matrix2Xd& x, const Point2& start, Space::Evaluator& evaluator,
                              std::vector<Point2>& reference, std::vector<bool>& inside) const {
  const CellShape shape = space_->cell_shape(element);
  const int q = static_cast<int>(x.cols());
  const double tol_x = 1e-12 * size_;
  reference.assign(q, start);
  inside.assign(q, false);
  // The rule object is reused, its points moved by Newton: evaluators detect changed points at a
  // reused address.
  thread_local QuadratureRule rule;
  thread_local PointValues pv;
  thread_local std::vector<char> done;
  thread_local std::vector<int> stalled;
  rule.points = reference;
  rule.weights.assign(q, 0.0);
  done.assign(q, 0);
  stalled.assign(q, 0);
  if (space_->affine_elements()) {
    // One Newton step is exact for an affine map.
    evaluator.evaluate_geometry(element, rule, pv);
    for (int k = 0; k < q; ++k) {
      const Eigen::Matrix2d& J = pv.jacobian[k];
      if (!(std::abs(J.determinant()) > 0.0)) continue;
      reference[k] = start - J.lu().solve(Point2(pv.x.col(k)) - x.col(k));
      inside[k] = inside_reference(shape, reference[k], 1e-10);
      if (!inside[k]) reference[k] = clamp_to_cell(shape, reference[k]);  // callers may evaluate there
    }
    return;
  }
  for (int it = 0; it < 30; ++it) {
    evaluator.evaluate_geometry(element, rule, pv);
    bool all_done = true;
    for (int k = 0; k < q; ++k) {
      if (done[k]) continue;
      const Point2 residual = Point2(pv.x.col(k)) - x.col(k);
      if (residual.norm() <= tol_x) {
        done[k] = 1;
        inside[k] = inside_reference(shape, rule.points[k], 1e-10);
        continue;
      }
      const Eigen::Matrix2d& J = pv.jacobian[k];
      if (!(std::abs(J.determinant()) > 0.0)) {
        done[k] = 1;
        continue;
      }
      const Point2 next = clamp_to_cell(shape, rule.points[k] - J.lu().solve(residual));
      // A point outside the element stops moving at the cell's boundary with a residual left.
      if ((next - rule.points[k]).norm() <= 1e-15 && ++stalled[k] >= 2) {
        done[k] = 1;
        continue;
      }
      rule.points[k] = next;
      all_done = false;
    }
    if (all_done) break;
  }
  reference = rule.points;
}

std::optional<PointLocation> PointLocator::locate(const Point2& x) const {
  const auto evaluator = space_->make_evaluator();
  return locate(x, *evaluator);
}

std::optional<PointLocation> PointLocator::locate(const Point2& x, Space::Evaluator& evaluator) const {
  thread_local std::vector<int> found;
  candidates(x, found);
  const Eigen::Matrix2Xd point = x;
  std::vector<Point2> reference;
  std::vector<bool> inside;
  for (int e : found) {
    const CellShape shape = space_->cell_shape(e);
    // Several starts: Newton from the centre may leave a strongly curved element.
    const std::vector<Point2> starts =
        shape == CellShape::quadrilateral
            ? std::vector<Point2>{{0.5, 0.5}, {0.2, 0.2}, {0.8, 0.2}, {0.8, 0.8}, {0.2, 0.8}}
            : std::vector<Point2>{{1.0 / 3, 1.0 / 3}, {0.15, 0.15}, {0.7, 0.15}, {0.15, 0.7}};
    for (const Point2& start : starts) {
      invert_map(e, point, start, evaluator, reference, inside);
      if (inside[0]) return PointLocation{e, reference[0]};
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
