#include "quadrature/quadrature_rule.hpp"

#include <algorithm>
#include <climits>
#include <cmath>

namespace iga {

QuadratureRule map_to_triangle(const QuadratureRule& ref, const Point2& a, const Point2& b, const Point2& c) {
  Eigen::Matrix2d J;
  J.col(0) = b - a;
  J.col(1) = c - a;
  // Reference area is 1/2, so the area ratio is |det J|; the orientation of (a, b, c) is irrelevant.
  const double scale = std::abs(J(0, 0) * J(1, 1) - J(0, 1) * J(1, 0));
  QuadratureRule rule;
  rule.degree = ref.degree;  // affine maps preserve polynomial degree
  rule.points.reserve(ref.size());
  rule.weights.reserve(ref.size());
  for (int k = 0; k < ref.size(); ++k) {
    rule.points.push_back(a + J * ref.points[k]);
    rule.weights.push_back(ref.weights[k] * scale);
  }
  return rule;
}

QuadratureRule map_to_box(const QuadratureRule& ref, const Point2& lo, const Point2& hi) {
  const Point2 h = hi - lo;
  const double scale = std::abs(h.x() * h.y());
  QuadratureRule rule;
  rule.degree = ref.degree;  // axis-aligned scaling keeps per-direction degree
  rule.points.reserve(ref.size());
  rule.weights.reserve(ref.size());
  for (int k = 0; k < ref.size(); ++k) {
    rule.points.push_back(lo + h.cwiseProduct(ref.points[k]));
    rule.weights.push_back(ref.weights[k] * scale);
  }
  return rule;
}

QuadratureRule concatenate(const std::vector<QuadratureRule>& parts) {
  QuadratureRule rule;
  if (parts.empty()) return rule;
  int degree = INT_MAX;
  for (const QuadratureRule& part : parts) {
    degree = std::min(degree, part.degree);
    rule.points.insert(rule.points.end(), part.points.begin(), part.points.end());
    rule.weights.insert(rule.weights.end(), part.weights.begin(), part.weights.end());
  }
  rule.degree = degree;  // the composite is only as exact as its weakest part
  return rule;
}

}  // namespace iga
