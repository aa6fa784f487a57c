#include "spaces/surface/reference_bernstein.hpp"

#include <array>
#include <cmath>

#include "geometry/rsd/bezier_triangle.hpp"

namespace iga {

ReferenceBernstein reference_bernstein(int p, const QuadratureRule& points, bool second) {
  const int n = bezier_count(p), q = points.size();
  ReferenceBernstein t;
  t.value.resize(n, q);
  t.dxi.resize(n, q);
  t.deta.resize(n, q);
  if (second) {
    t.dxixi.resize(n, q);
    t.dxieta.resize(n, q);
    t.detaeta.resize(n, q);
  }
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
        if (!second) continue;
        // ∂²B/∂λ_s∂λ_t = c a_s (a_t − δ_st) λ^(a − e_s − e_t); with dλ/dξ = (−1, 1, 0) and
        // dλ/dη = (−1, 0, 1): ∂ξξ = d11 − 2 d01 + d00, ∂ξη = d12 − d01 − d02 + d00, ∂ηη = d22 − 2 d02 + d00.
        const auto dd = [&](int s, int r) {
          std::array<int, 3> e = a;
          --e[s];
          --e[r];
          if (e[0] < 0 || e[1] < 0 || e[2] < 0) return 0.0;
          const double f = s == r ? a[s] * (a[s] - 1.0) : double(a[s]) * a[r];
          return c * f * power(l[0], e[0]) * power(l[1], e[1]) * power(l[2], e[2]);
        };
        const double d00 = dd(0, 0), d01 = dd(0, 1), d02 = dd(0, 2), d11 = dd(1, 1), d12 = dd(1, 2), d22 = dd(2, 2);
        t.dxixi(i, k) = d11 - 2 * d01 + d00;
        t.dxieta(i, k) = d12 - d01 - d02 + d00;
        t.detaeta(i, k) = d22 - 2 * d02 + d00;
      }
  }
  return t;
}

const ReferenceBernstein& ReferenceBernsteinCache::get(int degree, const QuadratureRule& points, bool second) {
  Entry& e = entries_[&points];
  const Point2 first = points.points.empty() ? Point2::Zero() : points.points.front();
  if (e.size != points.size() || e.first != first || e.table.value.rows() != bezier_count(degree) ||
      e.table.value.cols() != points.size() || (second && e.table.dxixi.size() == 0)) {
    e.size = points.size();
    e.first = first;
    e.table = reference_bernstein(degree, points, second);
  }
  return e.table;
}

}  // namespace iga
