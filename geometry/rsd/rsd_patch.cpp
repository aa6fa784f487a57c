#include "geometry/rsd/rsd_patch.hpp"

namespace iga::rsd {

namespace {

std::array<int, 3> unit(int a, int power) {
  std::array<int, 3> e{0, 0, 0};
  e[a] = power;
  return e;
}

std::array<int, 3> operator+(std::array<int, 3> x, const std::array<int, 3>& y) {
  for (int k = 0; k < 3; ++k) x[k] += y[k];
  return x;
}

int degree_of(const VecPoly<double>& z) { return degree(z); }

double binomial(int n, int k) {
  double value = 1;
  for (int l = 1; l <= k; ++l) value = value * (n - k + l) / l;
  return value;
}

}  // namespace

BezierTriangle rsd_patch(RsdTuple tuple, const TriangleData& data, const std::vector<LocalEdgeCorrection>& corrections,
                         int degree) {
  BarycentricPolynomial F(degree);
  const Poly<double> p0 = psi0<double>(tuple), p1 = psi1<double>(tuple);
  for (int a = 0; a < 3; ++a) {
    for (int k = 0; k <= p0.degree(); ++k)
      if (p0.c[k] != 0) F.add(unit(a, k), p0.c[k] * data.f[a]);
    for (int b = 0; b < 3; ++b) {
      if (b == a) continue;
      const int c = 3 - a - b;
      for (int k = 0; k <= p1.degree(); ++k)
        if (p1.c[k] != 0) F.add(unit(a, k) + unit(b, 1), p1.c[k] * data.g[a][b]);
      // χ0 and χ1 (corrected coefficients): t_a² t_b² t_c [15 f_a + 6 g_ab] (Π0) or
      // t_a² t_b² t_c [15 f_a + 15 t_b g_ab] (Π1).
      const auto bubble = unit(a, 2) + unit(b, 2) + unit(c, 1);
      F.add(bubble, 15.0 * data.f[a]);
      if (tuple == RsdTuple::pi0)
        F.add(bubble, 6.0 * data.g[a][b]);
      else
        F.add(bubble + unit(b, 1), 15.0 * data.g[a][b]);
    }
  }
  for (const auto& e : corrections) {
    const auto bubble = unit(e.a, 2) + unit(e.b, 2) + unit(e.c, 1);
    for (int k = 0; k <= degree_of(e.z); ++k) {
      const Eigen::Vector3d zk(e.z[0].coefficient(k), e.z[1].coefficient(k), e.z[2].coefficient(k));
      // −½ z(t_a): the term z_k t_a^k.
      F.add(bubble + unit(e.a, k), -0.5 * zk);
      // −½ z(t_a + t_c) = −½ Σ_l C(k, l) t_a^l t_c^(k−l).
      for (int l = 0; l <= k; ++l) F.add(bubble + unit(e.a, l) + unit(e.c, k - l), -0.5 * binomial(k, l) * zk);
    }
  }
  return F.bernstein();
}

}  // namespace iga::rsd
