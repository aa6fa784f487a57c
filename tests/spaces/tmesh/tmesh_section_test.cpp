// Univariate section spaces of generalized splines: G-basis, generalized Bernstein basis, stability.
#include <gtest/gtest.h>

#include <Eigen/LU>
#include <cmath>
#include <algorithm>
#include <cstdio>
#include <numbers>

#include "spaces/tmesh/section_space.hpp"

using namespace iga;

namespace {

constexpr double pi = std::numbers::pi;

SectionSpec trig(int n, double w) { return {SectionFamily::trigonometric, n, w}; }
SectionSpec hyp(int n, double w) { return {SectionFamily::hyperbolic, n, w}; }
SectionSpec poly(int n) { return {SectionFamily::polynomial, n, 0.0}; }

/// The exact generators of the section space and their derivatives at x: column 0..n.
Eigen::MatrixXd raw_generators(const SectionSpec& s, double x, int dmax) {
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(dmax + 1, s.n + 1);
  for (int d = 0; d <= dmax; ++d) {
    for (int k = 0; k <= s.n - 2; ++k)
      if (d <= k) out(d, k) = std::tgamma(k + 1) / std::tgamma(k - d + 1) * std::pow(x, k - d);
    const double w = s.w;
    for (int j = 0; j < 2; ++j) {
      double v;
      if (s.family == SectionFamily::trigonometric) {
        // d-th derivative of cos / sin.
        const double phase = (j == 0 ? 0.0 : -pi / 2) + d * pi / 2;
        v = std::pow(w, d) * std::cos(w * x + phase);
      } else if (s.family == SectionFamily::hyperbolic) {
        const bool even = (d + j) % 2 == 0;
        v = std::pow(w, d) * (even ? std::cosh(w * x) : std::sinh(w * x));
      } else {
        const int k = s.n - 1 + j;
        v = d <= k ? std::tgamma(k + 1) / std::tgamma(k - d + 1) * std::pow(x, k - d) : 0.0;
      }
      out(d, s.n - 1 + j) = v;
    }
  }
  return out;
}

}  // namespace

TEST(TmeshSection, GBasisSpansTheSectionSpaceAndDerivativesAreExact) {
  // Each scaled G-basis function is a combination of the raw generators (fit at n+1 points, then
  // compare values and derivatives at other points): reproduction of the section space.
  for (const SectionSpec& s : {trig(3, 1.3), hyp(4, 2.0), poly(5), trig(2, 0.7)}) {
    const double h = 1.1;
    const int n = s.n;
    Eigen::MatrixXd R(n + 1, n + 1), G(n + 1, n + 1);
    for (int p = 0; p <= n; ++p) {
      const double x = h * (p + 0.5) / (n + 1);
      R.row(p) = raw_generators(s, x, 0).row(0);
      G.row(p) = g_basis_scaled(n, s.pi_rho(), h, x / h, 0).row(0);
    }
    const Eigen::MatrixXd X = R.fullPivLu().solve(G);  // G-basis in raw generators
    for (double x : {0.0, 0.37, 0.8, 1.1}) {
      const Eigen::MatrixXd raw = raw_generators(s, x, 3);
      const Eigen::MatrixXd gs = g_basis_scaled(n, s.pi_rho(), h, x / h, 3);
      for (int d = 0; d <= 3; ++d) {
        const Eigen::RowVectorXd fit = raw.row(d) * X;
        for (int k = 0; k <= n; ++k) EXPECT_NEAR(fit(k) * std::pow(h, d), gs(d, k), 1e-10) << s.description();
      }
    }
  }
}

TEST(TmeshSection, BernsteinPartitionOfUnityZerosAndPositivity) {
  for (const SectionSpec& s : {trig(3, 1.7), trig(5, 1.9), hyp(5, 3.0), poly(4), trig(2, 1.0)}) {
    const double h = s.family == SectionFamily::trigonometric ? 0.9 * pi / s.w : 1.3;
    const SectionBernstein b(s, h);
    for (double t = 0.0; t <= 1.0; t += 0.05) {
      const Eigen::MatrixXd D = b.derivatives(t, 2);
      EXPECT_NEAR(D.row(0).sum(), 1.0, 1e-13);
      EXPECT_NEAR(D.row(1).sum(), 0.0, 1e-12);
      if (t > 0 && t < 0.999)
        for (int i = 0; i <= s.n; ++i) EXPECT_GT(D(0, i), 0.0) << s.description();
    }
    const Eigen::MatrixXd D0 = b.derivatives(0.0, s.n), D1 = b.derivatives(1.0, s.n);
    for (int i = 0; i <= s.n; ++i) {
      for (int j = 0; j < i; ++j) EXPECT_NEAR(D0(j, i), 0.0, 1e-13);
      for (int j = 0; j < s.n - i; ++j) EXPECT_NEAR(D1(j, i), 0.0, 1e-11);
      EXPECT_GT(std::abs(D0(i, i)), 1e-3);
    }
  }
}

TEST(TmeshSection, LeadingDerivativesMatchTheNotes) {
  // Values of B_i^{(i)}(0) from the notes §8.1 (physical derivatives).
  auto leading = [](const SectionSpec& s, double h) {
    const Eigen::MatrixXd D = SectionBernstein(s, h).derivatives(0.0, s.n);
    Eigen::VectorXd v(s.n + 1);
    for (int i = 0; i <= s.n; ++i) v(i) = D(i, i) / std::pow(h, i);
    return v;
  };
  const Eigen::VectorXd t5 = leading(trig(5, 1.9), pi / 2);
  const double et[] = {1, 2.92361, 7.21748, 14.45883, 20.74996, 15.45062};
  for (int i = 0; i <= 5; ++i) EXPECT_NEAR(t5(i), et[i], 1e-5 * et[i]);
  const Eigen::VectorXd h5 = leading(hyp(5, 3.0), pi / 2);
  const double eh[] = {1, 3.90079, 10.08798, 17.74682, 18.4854, 7.25352};
  for (int i = 0; i <= 5; ++i) EXPECT_NEAR(h5(i), eh[i], 1e-5 * eh[i]);
  const Eigen::VectorXd t2 = leading(trig(2, 1.0), 1.0);
  EXPECT_NEAR(t2(1), 1.830487, 1e-6);
  EXPECT_NEAR(t2(2), 2.175343, 1e-6);
  // n = 3 trig at w = 1.7, h = 1.3: B_1'(0) and B_2''(0).
  const Eigen::VectorXd t3 = leading(trig(3, 1.7), 1.3);
  EXPECT_NEAR(t3(1), 1.928443, 1e-6);
  EXPECT_NEAR(t3(2), 3.250632, 1e-6);
}

TEST(TmeshSection, ClosedFormCycloidalBasis) {
  // n = 3 trig closed form of the notes at alpha = w h = 1, theta = 0.3.
  const SectionBernstein b(trig(3, 1.0), 1.0);
  const Eigen::MatrixXd D = b.derivatives(0.3, 0);
  const double e[] = {0.351874467, 0.433018376, 0.186848649, 0.028258507};
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(D(0, i), e[i], 1e-9);
}

TEST(TmeshSection, StableForTinyAndNearCriticalLengths) {
  // w h = 1e-3: the trig basis must agree with the polynomial Bernstein basis to O((wh)^2), and
  // the leading derivatives with n!/((n-i)! h^i) (notes §8.1: w = 1e-4, h = 0.1).
  const int n = 5;
  const SectionBernstein t(trig(n, 1e-2), 0.1), p(poly(n), 0.1);
  for (double s = 0.0; s <= 1.0; s += 0.1) {
    const Eigen::MatrixXd a = t.derivatives(s, 2), c = p.derivatives(s, 2);
    EXPECT_LT((a - c).cwiseAbs().maxCoeff(), 1e-6);
    EXPECT_NEAR(a.row(0).sum(), 1.0, 1e-14);
  }
  const SectionBernstein tl(trig(n, 1e-4), 0.1);
  const double e[] = {1, 50, 2000, 60000, 1.2e6, 1.2e7};
  const Eigen::MatrixXd D0 = tl.derivatives(0.0, n);
  for (int i = 0; i <= n; ++i) EXPECT_NEAR(D0(i, i) / std::pow(0.1, i), e[i], 1e-8 * e[i]);
  // The trig basis is an even function of w h: B(2e-3) - B_poly must be 4 (B(1e-3) - B_poly) up to
  // O((wh)^4). The raw {poly, cos, sin} construction loses every digit here (notes P4).
  const SectionBernstein t1(trig(n, 1e-2), 0.1), t2(trig(n, 2e-2), 0.1);
  double worst = 0.0, size = 0.0;
  for (double s = 0.0; s <= 1.0; s += 0.05) {
    const Eigen::MatrixXd d1 = t1.derivatives(s, 2) - p.derivatives(s, 2), d2 = t2.derivatives(s, 2) - p.derivatives(s, 2);
    worst = std::max(worst, (d2 - 4 * d1).cwiseAbs().maxCoeff());
    size = std::max(size, d1.cwiseAbs().maxCoeff());
  }
  EXPECT_GT(size, 1e-9);  // the trigonometric correction is visible ...
  std::printf("w h = 1e-3: trig - poly %.3e, non-quadratic part %.3e\n", size, worst);
  EXPECT_LT(worst, 1e-4 * size);  // ... and smooth in (w h)^2, without round-off noise
  // Near pi the basis is still a positive partition of unity.
  const SectionBernstein near(trig(3, 1.0), pi - 1e-3);
  for (double s = 0.05; s < 1.0; s += 0.05) {
    const Eigen::MatrixXd D = near.derivatives(s, 1);
    EXPECT_NEAR(D.row(0).sum(), 1.0, 1e-12);
    EXPECT_GT(D.row(0).minCoeff(), 0.0);
  }
  // Symmetry of reflection-invariant spaces: B_i^{(n-i)}(h) = (-1)^{n-i} B_{n-i}^{(n-i)}(0).
  const SectionBernstein sym(hyp(4, 2.0), 0.8);
  const Eigen::MatrixXd S0 = sym.derivatives(0.0, 4), S1 = sym.derivatives(1.0, 4);
  for (int i = 0; i <= 4; ++i) EXPECT_NEAR(S1(4 - i, i), std::pow(-1.0, 4 - i) * S0(4 - i, 4 - i), 1e-10);
}

TEST(TmeshSection, RejectsTrigonometricCellsOfLengthPi) {
  try {
    SectionBernstein(trig(3, 1.0), pi);
    FAIL() << "w h = pi accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("w*h"), std::string::npos);
  }
  EXPECT_THROW(SectionBernstein(trig(1, 1.0), 1.0), std::invalid_argument);
  EXPECT_NO_THROW(SectionBernstein(hyp(3, 5.0), 2.0));
}
