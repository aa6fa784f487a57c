#include "spaces/surface/reference_bernstein.hpp"

#include <array>
#include <cmath>

#include "geometry/rsd/bezier_triangle.hpp"

namespace iga {

ReferenceBernstein reference_bernstein(int p, const QuadratureRule& points) {
  const int n = bezier_count(p), q = points.size();
  ReferenceBernstein t;
  t.value.resize(n, q);
  t.dxi.resize(n, q);
  t.deta.resize(n, q);
  std::array<double, 16> fact;
  fact[0] = 1;
  for (int k = 1; k <= p; ++k) fact[k] = fact[k - 1] * k;
  // λ^k with λ^(−1) never used (its factor α_a is zero then).
  const auto power = [](double x, int k) { return k <= 0 ? 1.0 : std::pow(x, k); };
  for (int k = 0; k < q; ++k) {
    const double xi = points.points[k].x(), eta = points.points[k].y();
    const std::array<double, 3> l = {1.0 - xi - eta, xi, eta};
    for (int a1 = p; a1 >= 0; --a1)
      for (int a2 = p - a1; a2 >= 0; --a2) {
        const std::array<int, 3> a = {a1, a2, p - a1 - a2};
        const double c = fact[p] / (fact[a[0]] * fact[a[1]] * fact[a[2]]);
        std::array<double, 3> pw, d;
        for (int s = 0; s < 3; ++s) pw[s] = power(l[s], a[s]);
        for (int s = 0; s < 3; ++s) d[s] = a[s] == 0 ? 0.0 : c * a[s] * power(l[s], a[s] - 1) * pw[(s + 1) % 3] * pw[(s + 2) % 3];
        const int i = bezier_index(p, a1, a2);
        t.value(i, k) = c * pw[0] * pw[1] * pw[2];
        t.dxi(i, k) = d[1] - d[0];
        t.deta(i, k) = d[2] - d[0];
      }
  }
  return t;
}

const ReferenceBernstein& ReferenceBernsteinCache::get(int degree, const QuadratureRule& points) {
  Entry& e = entries_[&points];
  const Point2 first = points.points.empty() ? Point2::Zero() : points.points.front();
  if (e.size != points.size() || e.first != first || e.table.value.rows() != bezier_count(degree) ||
      e.table.value.cols() != points.size()) {
    e.size = points.size();
    e.first = first;
    e.table = reference_bernstein(degree, points);
  }
  return e.table;
}

}  // namespace iga
