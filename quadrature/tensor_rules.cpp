#include "quadrature/quadrature_rule.hpp"

namespace iga {

QuadratureRule tensor_gauss(int degree) {
  const QuadratureRule line = gauss_legendre_for_degree(degree);
  const int n = line.size();
  QuadratureRule rule;
  rule.points.reserve(n * n);
  rule.weights.reserve(n * n);
  // The degree actually achieved (2n - 1 >= degree) per direction.
  rule.degree = line.degree;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      rule.points.emplace_back(line.points[i].x(), line.points[j].x());
      rule.weights.push_back(line.weights[i] * line.weights[j]);
    }
  }
  return rule;
}

}  // namespace iga
