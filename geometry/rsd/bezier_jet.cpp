#include "geometry/rsd/bezier_jet.hpp"

#include <vector>

namespace iga {

namespace {

/// All Bernstein polynomials of degree d at t, in bezier_index order.
void bernstein_all(int d, const Eigen::Vector3d& t, std::vector<double>& out) {
  out.assign(bezier_count(d), 0.0);
  if (d < 0) return;
  // pow[a][k] = t_a^k, and the multinomial d!/(a1! a2! a3!) from factorials (d ≤ 25: exact enough).
  std::array<std::array<double, 32>, 3> pw;
  std::array<double, 32> fact;
  fact[0] = 1;
  for (int k = 1; k <= d; ++k) fact[k] = fact[k - 1] * k;
  for (int a = 0; a < 3; ++a) {
    pw[a][0] = 1;
    for (int k = 1; k <= d; ++k) pw[a][k] = pw[a][k - 1] * t(a);
  }
  for (int a1 = d; a1 >= 0; --a1)
    for (int a2 = d - a1; a2 >= 0; --a2) {
      const int a3 = d - a1 - a2;
      out[bezier_index(d, a1, a2)] = fact[d] / (fact[a1] * fact[a2] * fact[a3]) * pw[0][a1] * pw[1][a2] * pw[2][a3];
    }
}

}  // namespace

BezierJet bezier_jet(const BezierTriangle& patch, const Eigen::Vector3d& t, bool second) {
  const int D = patch.degree;
  thread_local std::vector<double> b0, b1, b2;
  BezierJet jet;
  bernstein_all(D, t, b0);
  jet.x.setZero();
  for (size_t i = 0; i < b0.size(); ++i) jet.x += b0[i] * patch.control[i];
  for (auto& v : jet.d) v.setZero();
  for (auto& row : jet.dd)
    for (auto& v : row) v.setZero();
  if (D < 1) return jet;
  // ∂_a F = D Σ_{|β|=D−1} b_{β+e_a} B^{D−1}_β.
  bernstein_all(D - 1, t, b1);
  for (int a1 = D - 1; a1 >= 0; --a1)
    for (int a2 = D - 1 - a1; a2 >= 0; --a2) {
      const double w = D * b1[bezier_index(D - 1, a1, a2)];
      jet.d[0] += w * patch.control[bezier_index(D, a1 + 1, a2)];
      jet.d[1] += w * patch.control[bezier_index(D, a1, a2 + 1)];
      jet.d[2] += w * patch.control[bezier_index(D, a1, a2)];
    }
  if (!second || D < 2) return jet;
  // ∂_a∂_b F = D(D−1) Σ_{|γ|=D−2} b_{γ+e_a+e_b} B^{D−2}_γ.
  bernstein_all(D - 2, t, b2);
  for (int a1 = D - 2; a1 >= 0; --a1)
    for (int a2 = D - 2 - a1; a2 >= 0; --a2) {
      const double w = D * (D - 1) * b2[bezier_index(D - 2, a1, a2)];
      const auto c = [&](int e1, int e2) { return patch.control[bezier_index(D, a1 + e1, a2 + e2)]; };
      jet.dd[0][0] += w * c(2, 0);
      jet.dd[1][1] += w * c(0, 2);
      jet.dd[2][2] += w * c(0, 0);
      jet.dd[0][1] += w * c(1, 1);
      jet.dd[0][2] += w * c(1, 0);
      jet.dd[1][2] += w * c(0, 1);
    }
  jet.dd[1][0] = jet.dd[0][1];
  jet.dd[2][0] = jet.dd[0][2];
  jet.dd[2][1] = jet.dd[1][2];
  return jet;
}

}  // namespace iga
