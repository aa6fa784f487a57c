#include "quadrature/quadrature_rule.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

namespace iga {

namespace {

/// Sums weights of points closer than `tol` (the symmetrization makes exact and near duplicates,
/// e.g. every point on a median appears twice).
QuadratureRule merge_coincident(const std::vector<Point2>& pts, const std::vector<double>& w, double tol) {
  std::vector<int> order(pts.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return pts[a].x() < pts[b].x(); });
  std::vector<bool> used(pts.size(), false);
  QuadratureRule rule;
  for (std::size_t i = 0; i < order.size(); ++i) {
    const int p = order[i];
    if (used[p]) continue;
    double weight = w[p];
    for (std::size_t j = i + 1; j < order.size() && pts[order[j]].x() - pts[p].x() < tol; ++j) {
      const int q = order[j];
      if (!used[q] && std::abs(pts[q].y() - pts[p].y()) < tol) {
        weight += w[q];
        used[q] = true;
      }
    }
    rule.points.push_back(pts[p]);
    rule.weights.push_back(weight);
  }
  return rule;
}

}  // namespace

QuadratureRule triangle_rule_collapsed(int degree) {
  degree = std::max(degree, 0);
  // Duffy map x = s, y = t (1 - s), dx dy = (1 - s) ds dt: a total-degree-d polynomial becomes
  // degree d + 1 in s (with the Jacobian) and degree d in t.
  const QuadratureRule gs = gauss_legendre_for_degree(degree + 1);
  const QuadratureRule gt = gauss_legendre_for_degree(degree);
  std::vector<Point2> pts;
  std::vector<double> w;
  pts.reserve(6 * gs.size() * gt.size());
  w.reserve(pts.capacity());
  for (int i = 0; i < gs.size(); ++i) {
    const double s = gs.points[i].x();
    for (int j = 0; j < gt.size(); ++j) {
      const double t = gt.points[j].x();
      // Barycentric coordinates, each formed without cancellation.
      const std::array<double, 3> l = {(1.0 - s) * (1.0 - t), s, t * (1.0 - s)};
      const double wij = gs.weights[i] * gt.weights[j] * (1.0 - s) / 6.0;
      // Averaging over the six barycentric permutations keeps exactness (the polynomial space is
      // invariant under them) and makes the rule symmetric.
      static constexpr int perm[6][2] = {{1, 2}, {2, 1}, {0, 1}, {1, 0}, {0, 2}, {2, 0}};
      for (const auto& p : perm) {
        pts.emplace_back(l[p[0]], l[p[1]]);
        w.push_back(wij);
      }
    }
  }
  QuadratureRule rule = merge_coincident(pts, w, 1e-14);
  rule.degree = degree;
  return rule;
}

QuadratureRule triangle_rule(int degree) {
  degree = std::max(degree, 0);
  QuadratureRule tabulated = triangle_rule_tabulated(degree);
  if (tabulated.size() > 0) return tabulated;
  return triangle_rule_collapsed(degree);
}

}  // namespace iga
