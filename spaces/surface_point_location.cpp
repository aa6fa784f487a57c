#include "spaces/surface_point_location.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

namespace iga {

namespace {

/// The closest point of the reference cell to r (unit square, or the unit triangle).
Point2 clamp_into_surface_cell(CellShape shape, Point2 r) {
  r = r.cwiseMax(0.0).cwiseMin(1.0);
  if (shape == CellShape::triangle && r.sum() > 1.0) {
    const double excess = 0.5 * (r.sum() - 1.0);
    r = (r.array() - excess).max(0.0).matrix();
    if (r.sum() > 1.0) r /= r.sum();
  }
  return r;
}

}  // namespace

namespace {

/// Gauss–Newton on |X(ξ) − x|² in the closest elements (by samples); calls `found(location,
/// distance)` for each candidate in order of the samples' distance until it returns true.
template <class Found>
void surface_candidates(const Space& space, const Eigen::Vector3d& x, Space::Evaluator& evaluator, const Found& found) {
  // Nearest sample per element, then Newton in the closest few elements.
  std::vector<std::pair<double, int>> nearest;
  std::vector<Point2> start(space.num_elements());
  PointValues g;
  for (int e = 0; e < space.num_elements(); ++e) {
    const QuadratureRule rule = reference_samples(space.cell_shape(e));
    evaluator.evaluate_geometry(e, rule, g);
    double best = std::numeric_limits<double>::infinity();
    for (int k = 0; k < rule.size(); ++k)
      if (const double d = (g.x3.col(k) - x).norm(); d < best) {
        best = d;
        start[e] = rule.points[k];
      }
    nearest.emplace_back(best, e);
  }
  const std::size_t tries = std::min<std::size_t>(8, nearest.size());
  std::partial_sort(nearest.begin(), nearest.begin() + tries, nearest.end());
  for (std::size_t t = 0; t < tries; ++t) {
    const int e = nearest[t].second;
    const CellShape shape = space.cell_shape(e);
    QuadratureRule one;
    one.points = {start[e]};
    one.weights = {0.0};
    for (int it = 0; it < 50; ++it) {
      evaluator.evaluate_geometry(e, one, g);
      const Eigen::Vector3d r = g.x3.col(0) - x;
      const Eigen::Matrix<double, 3, 2>& J = g.jacobian3[0];
      const Eigen::Vector2d step = (J.transpose() * J).ldlt().solve(-J.transpose() * r);
      const Point2 next = clamp_into_surface_cell(shape, one.points[0] + step);
      const bool settled = (next - one.points[0]).norm() < 1e-14;
      one.points[0] = next;
      if (settled) break;
    }
    evaluator.evaluate_geometry(e, one, g);
    if (found(PointLocation{e, one.points[0]}, (g.x3.col(0) - x).norm())) return;
  }
}

}  // namespace

std::optional<PointLocation> locate_on_surface(const Space& space, const Eigen::Vector3d& x,
                                               Space::Evaluator& evaluator, double tolerance) {
  std::optional<PointLocation> out;
  surface_candidates(space, x, evaluator, [&](const PointLocation& at, double distance) {
    if (distance <= tolerance) out = at;
    return out.has_value();
  });
  return out;
}

std::optional<PointLocation> nearest_on_surface(const Space& space, const Eigen::Vector3d& x,
                                                Space::Evaluator& evaluator, double& distance) {
  std::optional<PointLocation> out;
  distance = std::numeric_limits<double>::infinity();
  surface_candidates(space, x, evaluator, [&](const PointLocation& at, double d) {
    if (d < distance) {
      distance = d;
      out = at;
    }
    return false;  // try every candidate: the nearest one wins
  });
  return out;
}

}  // namespace iga
