#include "geometry/rsd/bezier_triangle.hpp"

#include <cmath>
#include <stdexcept>

namespace iga {

namespace {

/// D!/(a1! a2! a3!) in double (exact for the degrees used here, D ≤ 30).
double multinomial(int a1, int a2, int a3) {
  double value = 1.0;
  int n = 0;
  for (int a : {a1, a2, a3})
    for (int k = 1; k <= a; ++k) value = value * (++n) / k;
  return value;
}

/// D!/(α1! α2! α3!) for every multi-index of degree D in bezier_index order, computed once per
/// degree (the table is built before any thread can use it: degrees up to 30 at first call).
const std::vector<double>& multinomials(int degree) {
  static const std::vector<std::vector<double>> table = [] {
    std::vector<std::vector<double>> t(31);
    for (int D = 0; D <= 30; ++D)
      for (int a1 = D; a1 >= 0; --a1)
        for (int a2 = D - a1; a2 >= 0; --a2) t[D].push_back(multinomial(a1, a2, D - a1 - a2));
    return t;
  }();
  if (degree < 0 || degree > 30) throw std::logic_error("BezierTriangle: degree above 30");
  return table[degree];
}

/// Powers t^0..t^D.
std::vector<double> powers(double t, int degree) {
  std::vector<double> p(degree + 1, 1.0);
  for (int k = 1; k <= degree; ++k) p[k] = p[k - 1] * t;
  return p;
}

Eigen::Vector3d evaluate(const std::vector<Eigen::Vector3d>& control, int degree, const Eigen::Vector3d& t) {
  const auto p1 = powers(t[0], degree), p2 = powers(t[1], degree), p3 = powers(t[2], degree);
  const std::vector<double>& weight = multinomials(degree);
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  int index = 0;
  for (int a1 = degree; a1 >= 0; --a1)
    for (int a2 = degree - a1; a2 >= 0; --a2, ++index)
      sum += (weight[index] * p1[a1] * p2[a2] * p3[degree - a1 - a2]) * control[index];
  return sum;
}

}  // namespace

int bezier_index(int degree, int a1, int a2) {
  // Rows a1 = D..a1+1 hold (D − a1' + 1) entries each.
  const int before = (degree - a1) * (degree - a1 + 1) / 2;
  return before + (degree - a1 - a2);
}

Eigen::Vector3d BezierTriangle::value(const Eigen::Vector3d& t) const { return evaluate(control, degree, t); }

std::array<Eigen::Vector3d, 3> BezierTriangle::partials(const Eigen::Vector3d& t) const {
  std::array<Eigen::Vector3d, 3> result;
  if (degree == 0) {
    result.fill(Eigen::Vector3d::Zero());
    return result;
  }
  // ∂/∂t_a = D Σ_{|β| = D−1} b_{β + e_a} B^{D−1}_β.
  for (int a = 0; a < 3; ++a) {
    std::vector<Eigen::Vector3d> lowered;
    lowered.reserve(bezier_count(degree - 1));
    for (int b1 = degree - 1; b1 >= 0; --b1)
      for (int b2 = degree - 1 - b1; b2 >= 0; --b2)
        lowered.push_back(control[bezier_index(degree, b1 + (a == 0), b2 + (a == 1))]);
    result[a] = degree * evaluate(lowered, degree - 1, t);
  }
  return result;
}

Eigen::Vector3d BezierTriangle::derivative(const Eigen::Vector3d& t, const Eigen::Vector3d& dt) const {
  const auto p = partials(t);
  return dt[0] * p[0] + dt[1] * p[1] + dt[2] * p[2];
}

BezierTriangle BezierTriangle::elevated() const {
  BezierTriangle up;
  up.degree = degree + 1;
  up.control.assign(bezier_count(up.degree), Eigen::Vector3d::Zero());
  const int D = up.degree;
  for (int a1 = D; a1 >= 0; --a1)
    for (int a2 = D - a1; a2 >= 0; --a2) {
      const int a3 = D - a1 - a2;
      Eigen::Vector3d sum = Eigen::Vector3d::Zero();
      if (a1 > 0) sum += double(a1) / D * control[bezier_index(degree, a1 - 1, a2)];
      if (a2 > 0) sum += double(a2) / D * control[bezier_index(degree, a1, a2 - 1)];
      if (a3 > 0) sum += double(a3) / D * control[bezier_index(degree, a1, a2)];
      up.control[bezier_index(D, a1, a2)] = sum;
    }
  return up;
}

BarycentricPolynomial::BarycentricPolynomial(int degree)
    : degree_(degree), monomial_(bezier_count(degree), Eigen::Vector3d::Zero()) {}

void BarycentricPolynomial::add(const std::array<int, 3>& a, const Eigen::Vector3d& coefficient) {
  const int r = a[0] + a[1] + a[2];
  if (r > degree_) throw std::logic_error("BarycentricPolynomial: a term above the patch degree");
  const int m = degree_ - r;  // multiply by (t1 + t2 + t3)^m
  for (int b1 = m; b1 >= 0; --b1)
    for (int b2 = m - b1; b2 >= 0; --b2)
      monomial_[bezier_index(degree_, a[0] + b1, a[1] + b2)] += multinomial(b1, b2, m - b1 - b2) * coefficient;
}

BezierTriangle BarycentricPolynomial::bernstein() const {
  BezierTriangle patch;
  patch.degree = degree_;
  patch.control.resize(monomial_.size());
  for (int a1 = degree_; a1 >= 0; --a1)
    for (int a2 = degree_ - a1; a2 >= 0; --a2) {
      const int index = bezier_index(degree_, a1, a2);
      patch.control[index] = monomial_[index] / multinomial(a1, a2, degree_ - a1 - a2);
    }
  return patch;
}

}  // namespace iga
