#include "spaces/tmesh/section_space.hpp"

#include <Eigen/LU>
#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>

namespace iga {

double SectionSpec::pi_rho() const {
  switch (family) {
    case SectionFamily::trigonometric: return w * w;
    case SectionFamily::hyperbolic: return -w * w;
    default: return 0.0;
  }
}

std::string SectionSpec::description() const {
  std::ostringstream s;
  if (family == SectionFamily::polynomial)
    s << "poly";
  else
    s << (family == SectionFamily::trigonometric ? "trig" : "hyperbolic") << " w=" << w;
  s << " n=" << n;
  return s.str();
}

namespace {

/// t^p / p! for p >= 0.
double power_over_factorial(double t, int p) {
  double v = 1.0;
  for (int k = 1; k <= p; ++k) v *= t / k;
  return v;
}

/// h^{d-m} G_m^{(d)}(x) = sum_{i: m+2i >= d} c^i t^{m+2i-d} / (m+2i-d)!, c = -pi_rho h^2.
double g_scaled(int m, int d, double c, double t) {
  int i = 0;
  while (m + 2 * i < d) ++i;
  int p = m + 2 * i - d;
  double term = std::pow(c, i) * power_over_factorial(t, p);
  double sum = term;
  if (c == 0.0) return sum;
  for (int k = 0; k < 400; ++k) {
    term *= c * t * t / ((p + 1.0) * (p + 2.0));
    p += 2;
    sum += term;
    if (std::abs(term) <= 1e-18 * std::abs(sum) && p > 2 * std::abs(c) + 4) break;
    if (term == 0.0) break;
  }
  return sum;
}

}  // namespace

Eigen::MatrixXd g_basis_scaled(int n, double pi_rho, double h, double t, int dmax) {
  const double c = -pi_rho * h * h;
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(dmax + 1, n + 1);
  for (int d = 0; d <= dmax; ++d) {
    for (int k = 0; k <= n - 2; ++k)
      if (d <= k) out(d, k) = power_over_factorial(t, k - d);
    for (int m = n - 1; m <= n; ++m) out(d, m) = g_scaled(m, d, c, t);
  }
  return out;
}

SectionBernstein::SectionBernstein(const SectionSpec& spec, double h) : spec_(spec), h_(h) {
  const int n = spec.n;
  if (n < 2) throw std::invalid_argument("section spaces need n >= 2 (got n = " + std::to_string(n) + ")");
  if (!(h > 0.0)) throw std::invalid_argument("section space interval length must be positive");
  if (spec.family != SectionFamily::polynomial && !(spec.w > 0.0))
    throw std::invalid_argument("the frequency w of a " + spec.description() + " section space must be > 0");
  if (spec.family == SectionFamily::trigonometric && spec.w * h >= std::numbers::pi) {
    std::ostringstream s;
    s << "trigonometric section space with w*h = " << spec.w * h << " >= pi (w = " << spec.w << ", cell length h = "
      << h << "): the generalized Bernstein basis degenerates; refine the mesh or lower w so that w*h < pi";
    throw std::invalid_argument(s.str());
  }
  const double pr = spec.pi_rho();
  const Eigen::MatrixXd at1 = g_basis_scaled(n, pr, h, 1.0, n);
  // At t = 0 the scaled G-basis Taylor matrix is the identity (d <= n), so conditions at 0 are
  // unit rows. beta_i: order-i zero at 0 with scaled i-th derivative 1, order-(n-i) zero at h.
  Eigen::MatrixXd beta(n + 1, n + 1);
  for (int i = 0; i <= n; ++i) {
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n + 1, n + 1);
    Eigen::VectorXd b = Eigen::VectorXd::Zero(n + 1);
    for (int j = 0; j <= i; ++j) A(j, j) = 1.0;
    b(i) = 1.0;
    for (int j = 0; j < n - i; ++j) A.row(i + 1 + j) = at1.row(j);
    beta.row(i) = A.fullPivLu().solve(b).transpose();
  }
  // Scales from the partition of unity, row by row of the Taylor data at 0.
  Eigen::VectorXd sigma(n + 1);
  sigma(0) = 1.0 / beta(0, 0);
  for (int j = 1; j <= n; ++j) {
    double s = 0.0;
    for (int i = 0; i < j; ++i) s -= sigma(i) * beta(i, j);
    sigma(j) = s;
  }
  coef_ = sigma.asDiagonal() * beta;
}

Eigen::MatrixXd SectionBernstein::derivatives(double t, int dmax) const {
  const Eigen::MatrixXd g = g_basis_scaled(spec_.n, spec_.pi_rho(), h_, t, dmax);
  return g * coef_.transpose();
}

}  // namespace iga
