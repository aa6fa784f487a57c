#include "quadrature/quadrature_rule.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace iga {

namespace {

/// P_n(t) and P_n'(t) by the three-term recurrence, in long double so the Newton roots and the
/// weights 2 / ((1 - t^2) P_n'(t)^2) keep full double accuracy up to n ~ 100.
void legendre_with_derivative(int n, long double t, long double& p, long double& dp) {
  long double p0 = 1.0L, p1 = t;
  for (int k = 2; k <= n; ++k) {
    const long double p2 = ((2 * k - 1) * t * p1 - (k - 1) * p0) / k;
    p0 = p1;
    p1 = p2;
  }
  p = (n == 0) ? 1.0L : p1;
  // Derivative from P_{n-1}, P_n; safe because Gauss roots are never at t = +-1.
  dp = n * (t * p1 - p0) / (t * t - 1.0L);
}

}  // namespace

QuadratureRule gauss_legendre(int n) {
  if (n < 1) throw std::invalid_argument("gauss_legendre: n must be >= 1, got " + std::to_string(n));
  QuadratureRule rule;
  rule.points.assign(n, Point2::Zero());
  rule.weights.assign(n, 0.0);
  rule.degree = 2 * n - 1;
  // Roots of P_n on [-1,1] come in +-t pairs: find the non-negative ones and mirror them,
  // so the rule on [0,1] is exactly symmetric about 1/2.
  for (int i = 0; i < (n + 1) / 2; ++i) {
    // Tricomi's asymptotic guess is close enough for quadratic Newton convergence.
    long double t = std::cos(std::numbers::pi_v<long double> * (i + 0.75L) / (n + 0.5L));
    long double p = 0, dp = 1;
    for (int it = 0; it < 100; ++it) {
      legendre_with_derivative(n, t, p, dp);
      const long double step = p / dp;
      t -= step;
      if (std::fabs(step) <= 1e-19L * std::fabs(t) + 1e-30L) break;
    }
    legendre_with_derivative(n, t, p, dp);
    if (2 * i + 1 == n) t = 0.0L;  // the middle root of odd n is exactly 0
    const long double w = 1.0L / ((1.0L - t * t) * dp * dp);  // half of the [-1,1] weight
    // Index i holds the root nearest +1; store ascending on [0,1].
    const int hi = n - 1 - i, lo = i;
    rule.points[hi].x() = static_cast<double>((1.0L + t) / 2.0L);
    rule.points[lo].x() = static_cast<double>((1.0L - t) / 2.0L);
    rule.weights[hi] = rule.weights[lo] = static_cast<double>(w);
  }
  return rule;
}

QuadratureRule gauss_legendre_for_degree(int degree) {
  if (degree < 0) degree = 0;
  return gauss_legendre(degree / 2 + 1);  // smallest n with 2n - 1 >= degree
}

}  // namespace iga
