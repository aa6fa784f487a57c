#include "spaces/tmesh/refinement_targets.hpp"

#include <algorithm>
#include <cmath>

namespace iga {

namespace {

/// The segment p + s (q - p), s in [0, 1], meets the box [lo, hi] (Liang–Barsky clipping).
bool segment_meets_box(const Eigen::Vector2d& p, const Eigen::Vector2d& q, const Eigen::Vector2d& lo,
                       const Eigen::Vector2d& hi) {
  double s0 = 0.0, s1 = 1.0;
  const Eigen::Vector2d d = q - p;
  for (int k = 0; k < 2; ++k) {
    if (d[k] == 0.0) {
      if (p[k] < lo[k] || p[k] > hi[k]) return false;
      continue;
    }
    double a = (lo[k] - p[k]) / d[k], b = (hi[k] - p[k]) / d[k];
    if (a > b) std::swap(a, b);
    s0 = std::max(s0, a);
    s1 = std::min(s1, b);
    if (s0 > s1) return false;
  }
  return true;
}

}  // namespace

std::vector<int> cells_meeting(const TMesh& mesh, const RefinementTarget& target) {
  const Eigen::Vector2d lo_all = mesh.point(mesh.bound(0), mesh.bound(2)), hi_all = mesh.point(mesh.bound(1), mesh.bound(3));
  const double eps = 1e-12 * (hi_all - lo_all).norm();
  const Eigen::Vector2d pad(eps, eps);
  std::vector<int> out;
  for (int c = 0; c < mesh.num_cells(); ++c) {
    const TCell& cell = mesh.cells()[c];
    const Eigen::Vector2d lo = mesh.point(cell.x0, cell.y0) - pad, hi = mesh.point(cell.x1, cell.y1) + pad;
    bool meets = false;
    switch (target.kind) {
      case RefinementTarget::Kind::point:
        meets = (target.points[0].array() >= lo.array()).all() && (target.points[0].array() <= hi.array()).all();
        break;
      case RefinementTarget::Kind::box:  // overlap of positive area: touching neighbours do not count
        meets = (target.points[0].array() < hi.array() - 2 * eps).all() &&
                (target.points[1].array() > lo.array() + 2 * eps).all();
        break;
      case RefinementTarget::Kind::polyline:
        for (std::size_t k = 0; k + 1 < target.points.size() && !meets; ++k)
          meets = segment_meets_box(target.points[k], target.points[k + 1], lo, hi);
        break;
    }
    if (meets) out.push_back(c);
  }
  return out;
}

}  // namespace iga
