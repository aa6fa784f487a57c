/// @file
/// Univariate B-splines: knot vectors, Cox–de Boor values and derivatives, Bernstein polynomials,
/// Bézier extraction and knot insertion (BSpline* tests).

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <random>
#include <stdexcept>

#include "spaces/bspline/bspline_basis_1d.hpp"
#include "spaces/bspline/knot_vector.hpp"

namespace iga {
namespace {

/// Increasing breakpoints on [0,1] with random spacing (ratio up to about 1:4).
std::vector<double> random_breakpoints(int elements, std::mt19937& rng) {
  std::uniform_real_distribution<double> len(0.5, 2.0);
  std::vector<double> bp{0.0};
  for (int i = 0; i < elements; ++i) bp.push_back(bp.back() + len(rng));
  for (double& t : bp) t /= bp.back();
  bp.back() = 1.0;
  return bp;
}

/// All n B-splines at t (row vector of the collocation matrix).
Eigen::RowVectorXd full_row(const KnotVector& kv, double t) {
  Eigen::RowVectorXd row = Eigen::RowVectorXd::Zero(kv.num_functions());
  const int mu = kv.find_span(t);
  const Eigen::MatrixXd d = bspline_derivatives(kv, mu, t, 0);
  for (int j = 0; j <= kv.degree(); ++j) row(mu - kv.degree() + j) = d(0, j);
  return row;
}

TEST(BSplineKnotVector, SizesSpansAndLookup) {
  const KnotVector kv = KnotVector::from_breakpoints(3, 1, {0.0, 0.25, 0.5, 1.0});
  // 4 + 2*2 + 4 knots, n = 12 - 4 = 8 = 3*(3-1) + 1 + 1.
  EXPECT_EQ(kv.size(), 12);
  EXPECT_EQ(kv.num_functions(), 8);
  EXPECT_EQ(kv.num_spans(), 3);
  EXPECT_EQ(kv.spans(), (std::vector<int>{3, 5, 7}));
  EXPECT_EQ(kv.find_span(0.0), 3);
  EXPECT_EQ(kv.find_span(0.1), 3);
  EXPECT_EQ(kv.find_span(0.25), 5);  // a knot belongs to the span on its right
  EXPECT_EQ(kv.find_span(0.7), 7);
  EXPECT_EQ(kv.find_span(1.0), 7);   // the right end belongs to the last span
  EXPECT_EQ(kv.multiplicity(0.25), 2);
  EXPECT_EQ(kv.multiplicity(0.3), 0);
  EXPECT_EQ(kv.max_interior_multiplicity(), 2);
  EXPECT_EQ(kv.breakpoints(), (std::vector<double>{0.0, 0.25, 0.5, 1.0}));

  for (int p = 1; p <= 5; ++p)
    for (int r = -1; r < p; ++r)
      for (int n : {1, 2, 7}) {
        const KnotVector u = KnotVector::uniform(p, r, n);
        EXPECT_EQ(u.num_functions(), n * (p - r) + r + 1) << p << " " << r << " " << n;
        EXPECT_EQ(u.num_spans(), n);
      }
}

TEST(BSplineKnotVector, RejectsInvalidKnots) {
  EXPECT_THROW(KnotVector(2, {0, 0, 1, 1, 1}), std::invalid_argument);        // left end not open
  EXPECT_THROW(KnotVector(1, {0, 0, 0.5, 0.4, 1, 1}), std::invalid_argument); // decreasing
  EXPECT_THROW(KnotVector(1, {0, 0, 0, 1, 1}), std::invalid_argument);        // end repeated p+2 times
  EXPECT_THROW(KnotVector(1, {1, 1, 1, 1}), std::invalid_argument);           // empty interval
  EXPECT_THROW(KnotVector::from_breakpoints(2, 2, {0, 1}), std::invalid_argument);
  EXPECT_THROW(KnotVector::from_breakpoints(2, 1, {0, 0.5, 0.5, 1}), std::invalid_argument);
}

TEST(BSplineKnotVector, UniformRefinementInsertsMidpoints) {
  const KnotVector coarse = KnotVector::from_breakpoints(3, 1, {0.0, 0.25, 1.0});
  const KnotVector fine = coarse.refined(2);
  EXPECT_EQ(fine.breakpoints(), (std::vector<double>{0.0, 0.125, 0.25, 0.625, 1.0}));
  EXPECT_EQ(fine.multiplicity(0.125), 2);
  EXPECT_EQ(fine.multiplicity(0.625), 2);
  EXPECT_EQ(fine.num_functions(), 4 * 2 + 2);
  EXPECT_TRUE(fine.refines(coarse));
  EXPECT_FALSE(coarse.refines(fine));
  EXPECT_FALSE(coarse.refined(1).refines(KnotVector::from_breakpoints(3, 0, {0.0, 0.25, 1.0})));
}

TEST(BSplineBasis, PartitionOfUnity) {
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> unif(0.0, 1.0);
  double worst = 0.0, worst_deriv = 0.0;
  for (int p = 1; p <= 5; ++p)
    for (int r = -1; r < p; ++r) {
      const KnotVector kv = KnotVector::from_breakpoints(p, r, random_breakpoints(6, rng));
      for (int s = 0; s < 200; ++s) {
        const double t = s == 0 ? 0.0 : s == 1 ? 1.0 : unif(rng);
        const Eigen::MatrixXd d = bspline_derivatives(kv, kv.find_span(t), t, 2);
        EXPECT_GE(d.row(0).minCoeff(), -1e-15);
        worst = std::max(worst, std::abs(d.row(0).sum() - 1.0));
        worst_deriv = std::max(worst_deriv, std::abs(d.row(1).sum()) / (1.0 + d.row(1).cwiseAbs().sum()));
        worst_deriv = std::max(worst_deriv, std::abs(d.row(2).sum()) / (1.0 + d.row(2).cwiseAbs().sum()));
      }
    }
  EXPECT_LT(worst, 1e-14);
  EXPECT_LT(worst_deriv, 1e-13);
  std::printf("[ measured ] |sum N - 1| %.2e, |sum N'|, |sum N''| (relative) %.2e\n", worst, worst_deriv);
}

TEST(BSplineBasis, SpanDerivativesOnTheStackAndAboveIt) {
  // SpanDerivatives keeps degree <= 15 with orders <= 2 on the stack and the rest on the heap: on
  // both sides of that bound the functions sum to one, their derivatives to zero, and the entries
  // are bspline_derivatives' (k, j).
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unif(0.0, 1.0);
  for (int p : {2, 15, 16, 21})
    for (int nder : {0, 2, 3}) {
      const KnotVector kv = KnotVector::from_breakpoints(p, p - 1, random_breakpoints(4, rng));
      for (int s = 0; s < 20; ++s) {
        const double t = unif(rng);
        const int mu = kv.find_span(t);
        const SpanDerivatives d(kv, mu, t, nder);
        const Eigen::MatrixXd e = bspline_derivatives(kv, mu, t, nder);
        double sum = 0.0;
        for (int j = 0; j <= p; ++j) {
          sum += d(0, j);
          for (int k = 0; k <= nder; ++k) ASSERT_EQ(d(k, j), e(k, j)) << "p " << p << " (" << k << ", " << j << ")";
        }
        EXPECT_NEAR(sum, 1.0, 1e-13) << "p " << p;
        for (int k = 1; k <= nder; ++k) {
          double dk = 0.0, size = 0.0;
          for (int j = 0; j <= p; ++j) {
            dk += d(k, j);
            size += std::abs(d(k, j));
          }
          EXPECT_LT(std::abs(dk), 1e-12 * (1.0 + size)) << "p " << p << " order " << k;
        }
      }
    }
}

TEST(BSplineBasis, DerivativesMatchCentralDifferences) {
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> unif(0.05, 0.95);
  const double h = 1e-6;
  double worst = 0.0;
  for (int p = 1; p <= 5; ++p)
    for (int r = 0; r < p; ++r) {
      const KnotVector kv = KnotVector::from_breakpoints(p, r, random_breakpoints(5, rng));
      for (int mu : kv.spans())
        for (int s = 0; s < 5; ++s) {
          // Points well inside the span so t +- h stays on the same polynomial piece.
          const double t = kv[mu] + unif(rng) * (kv[mu + 1] - kv[mu]);
          const int nder = std::min(p, 4);
          const Eigen::MatrixXd d = bspline_derivatives(kv, mu, t, nder);
          const Eigen::MatrixXd dp = bspline_derivatives(kv, mu, t + h, nder);
          const Eigen::MatrixXd dm = bspline_derivatives(kv, mu, t - h, nder);
          for (int k = 1; k <= nder; ++k) {
            const Eigen::RowVectorXd fd = (dp.row(k - 1) - dm.row(k - 1)) / (2 * h);
            const double scale = std::max(1.0, d.row(k).cwiseAbs().maxCoeff());
            worst = std::max(worst, (fd - d.row(k)).cwiseAbs().maxCoeff() / scale);
          }
          // Orders above p vanish.
          EXPECT_EQ(bspline_derivatives(kv, mu, t, p + 1).row(p + 1).cwiseAbs().maxCoeff(), 0.0);
        }
    }
  EXPECT_LT(worst, 1e-6);
  std::printf("[ measured ] central differences vs Cox-de Boor derivatives: %.2e (relative)\n", worst);
}

TEST(BSplineBasis, BernsteinPolynomials) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unif(0.0, 1.0);
  const double h = 1e-6;
  for (int p = 0; p <= 6; ++p)
    for (int s = 0; s < 20; ++s) {
      const double u = unif(rng);
      const Eigen::MatrixXd b = bernstein_derivatives(p, u, 3);
      EXPECT_NEAR(b.row(0).sum(), 1.0, 1e-14);
      for (int i = 0; i <= p; ++i) {
        double binom = 1.0;
        for (int k = 1; k <= i; ++k) binom = binom * (p - i + k) / k;
        EXPECT_NEAR(b(0, i), binom * std::pow(u, i) * std::pow(1 - u, p - i), 1e-14);
      }
      if (u < h || u > 1 - h) continue;
      const Eigen::MatrixXd bp = bernstein_derivatives(p, u + h, 3), bm = bernstein_derivatives(p, u - h, 3);
      for (int k = 1; k <= 3; ++k) {
        const Eigen::RowVectorXd fd = (bp.row(k - 1) - bm.row(k - 1)) / (2 * h);
        const double scale = std::max(1.0, b.row(k).cwiseAbs().maxCoeff());
        EXPECT_LT((fd - b.row(k)).cwiseAbs().maxCoeff() / scale, 1e-6) << "p " << p << " order " << k;
      }
    }
}

/// Knot vectors for the extraction tests: every regularity of uniform and random breakpoints,
/// plus random mixed multiplicities.
std::vector<KnotVector> sample_knot_vectors(int p, std::mt19937& rng) {
  std::vector<KnotVector> out;
  for (int r = -1; r < p; ++r) {
    out.push_back(KnotVector::uniform(p, r, 4));
    out.push_back(KnotVector::from_breakpoints(p, r, random_breakpoints(5, rng)));
  }
  std::uniform_int_distribution<int> mult(1, p + 1);
  const std::vector<double> bp = random_breakpoints(6, rng);
  std::vector<double> knots(p + 1, 0.0);
  for (size_t i = 1; i + 1 < bp.size(); ++i) knots.insert(knots.end(), mult(rng), bp[i]);
  knots.insert(knots.end(), p + 1, 1.0);
  out.emplace_back(p, knots);
  return out;
}

TEST(BSplineBasis, BezierExtractionReproducesCoxDeBoor) {
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> unif(0.0, 1.0);
  double worst = 0.0;
  int elements = 0;
  for (int p = 1; p <= 5; ++p)
    for (const KnotVector& kv : sample_knot_vectors(p, rng)) {
      const std::vector<Eigen::MatrixXd> C = bezier_extractions(kv);
      ASSERT_EQ(static_cast<int>(C.size()), kv.num_spans());
      for (int e = 0; e < kv.num_spans(); ++e) {
        ++elements;
        const int mu = kv.spans()[e];
        const double a = kv[mu], len = kv[mu + 1] - a;
        for (int s = 0; s < 8; ++s) {
          const double xi = s == 0 ? 0.0 : s == 1 ? 1.0 : unif(rng);
          const Eigen::MatrixXd ref = bspline_derivatives(kv, mu, a + xi * len, 2);
          const Eigen::MatrixXd bern = bernstein_derivatives(p, xi, 2);
          for (int k = 0; k <= 2; ++k) {
            // d/dt = (1/len) d/dxi.
            const Eigen::VectorXd ext = C[e] * bern.row(k).transpose() / std::pow(len, k);
            const double scale = std::max(1.0, ref.row(k).cwiseAbs().maxCoeff());
            worst = std::max(worst, (ext - ref.row(k).transpose()).cwiseAbs().maxCoeff() / scale);
          }
        }
      }
    }
  EXPECT_GT(elements, 100);
  EXPECT_LT(worst, 1e-12);
  std::printf("[ measured ] extraction vs Cox-de Boor on %d elements: %.2e\n", elements, worst);
}

TEST(BSplineBasis, ExtractionOfBezierKnotsIsIdentity) {
  // With every interior knot of multiplicity p the B-splines are the Bernstein polynomials.
  const KnotVector kv = KnotVector::uniform(3, 0, 3);
  for (const Eigen::MatrixXd& C : bezier_extractions(kv))
    EXPECT_LT((C - Eigen::MatrixXd::Identity(4, 4)).cwiseAbs().maxCoeff(), 1e-15);
}

TEST(BSplineBasis, KnotInsertionKeepsCoarseFunctions) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unif(0.0, 1.0);
  double worst = 0.0;
  for (int p = 1; p <= 5; ++p)
    for (int r = 0; r < p; ++r) {
      const KnotVector coarse = KnotVector::from_breakpoints(p, r, random_breakpoints(4, rng));
      // Uniform refinement, then a few random extra knots.
      const KnotVector fine = coarse.refined(p - r).with_knots({unif(rng), unif(rng)});
      ASSERT_TRUE(fine.refines(coarse));
      const Eigen::VectorXd c = Eigen::VectorXd::Random(coarse.num_functions());
      const int m = 20 * fine.num_functions();
      Eigen::MatrixXd A(m, fine.num_functions());
      Eigen::VectorXd f(m);
      for (int s = 0; s < m; ++s) {
        const double t = double(s) / (m - 1);
        A.row(s) = full_row(fine, t);
        f(s) = full_row(coarse, t).dot(c);
      }
      const Eigen::VectorXd d = A.colPivHouseholderQr().solve(f);
      worst = std::max(worst, (A * d - f).cwiseAbs().maxCoeff());
    }
  EXPECT_LT(worst, 1e-12);
  std::printf("[ measured ] least-squares residual of coarse functions in the refined space: %.2e\n", worst);
}

}  // namespace
}  // namespace iga
