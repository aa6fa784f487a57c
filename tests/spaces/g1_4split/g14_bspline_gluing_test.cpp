// The univariate layer (notes §12.1) and the gluing data (§12.2) of the 4-split G1 space.
#include <gtest/gtest.h>

#include <cmath>

#include "spaces/bspline/bspline_basis_1d.hpp"
#include "spaces/g1_4split/gluing.hpp"
#include "spaces/g1_4split/split_bspline.hpp"

namespace iga {
namespace {

TEST(G14BSpline, QuarticC1TableOfTheNotes) {
  const SplitBSpline b(4, 1);
  ASSERT_EQ(b.size(), 8);
  for (double t : {0.0, 0.1, 0.25, 0.37, 0.5, 0.61, 0.8, 1.0}) {
    const Eigen::MatrixXd N = b.derivatives(t, 0);
    const bool L = t < 0.5;
    const double u = 1 - 2 * t, w = 2 * t - 1, s = 1 - t;
    const double expect[8] = {L ? std::pow(u, 4) : 0,
                              L ? 8 * t * std::pow(u, 3) : 0,
                              L ? 24 * t * t * u * u : 0,
                              L ? 8 * std::pow(t, 3) * (4 - 7 * t) : 8 * std::pow(s, 4),
                              L ? 8 * std::pow(t, 4) : 8 * std::pow(s, 3) * (7 * t - 3),
                              L ? 0 : 24 * s * s * w * w,
                              L ? 0 : 8 * s * std::pow(w, 3),
                              L ? 0 : std::pow(w, 4)};
    for (int i = 0; i < 8; ++i) EXPECT_NEAR(N(0, i), expect[i], 1e-14) << "t=" << t << " i=" << i;
  }
  const Eigen::MatrixXd D = b.derivatives(0.0, 1);
  EXPECT_NEAR(D(1, 0), -8.0, 1e-13);
  EXPECT_NEAR(D(1, 1), 8.0, 1e-13);
  EXPECT_NEAR(D.row(1).tail(6).cwiseAbs().maxCoeff(), 0.0, 1e-13);
  // At 1/2 only N3, N4 are non-zero, 1/2 each.
  const Eigen::MatrixXd H = b.derivatives(0.5, 0);
  EXPECT_NEAR(H(0, 3), 0.5, 1e-15);
  EXPECT_NEAR(H(0, 4), 0.5, 1e-15);
}

TEST(G14BSpline, DimensionPartitionOfUnityAndSmoothnessAtTheSplit) {
  for (int k = 2; k <= 8; ++k)
    for (int r = 0; r < k; ++r) {
      const SplitBSpline b(k, r);
      ASSERT_EQ(b.size(), 2 * k + 1 - r);
      for (double t : {0.0, 0.2, 0.5, 0.7, 1.0}) EXPECT_NEAR(b.derivatives(t, 0).sum(), 1.0, 1e-13);
      // Derivatives up to order r agree from both sides of 1/2, order r+1 does not (for k > r).
      const int order = std::min(r + 1, 2);
      const Eigen::MatrixXd left = b.derivatives(0.5, order, 0), right = b.derivatives(0.5, order, 1);
      for (int d = 0; d <= std::min(r, order); ++d)
        EXPECT_LT((left.row(d) - right.row(d)).cwiseAbs().maxCoeff(), 1e-10 * std::pow(2.0 * k, d)) << k << r << d;
      if (r + 1 <= 2) EXPECT_GT((left.row(r + 1) - right.row(r + 1)).cwiseAbs().maxCoeff(), 1.0);
      // The Bernstein extraction reproduces the pieces.
      for (int h = 0; h < 2; ++h)
        for (double s : {0.0, 0.3, 1.0}) {
          const Eigen::VectorXd viaB = b.bernstein_extraction(h).transpose() * bernstein_derivatives(k, s, 0).row(0).transpose();
          const Eigen::MatrixXd direct = b.derivatives(0.5 * (h + s), 0, h);
          EXPECT_LT((viaB.transpose() - direct.row(0)).cwiseAbs().maxCoeff(), 1e-12);
        }
    }
}

TEST(G14Gluing, ValuesOfTheNotes) {
  EXPECT_NEAR(vertex_gluing_value(3, false), -1.0, 1e-15);
  EXPECT_EQ(vertex_gluing_value(4, false), 0.0);
  EXPECT_NEAR(vertex_gluing_value(5, false), 0.6180339887498949, 1e-15);
  EXPECT_NEAR(vertex_gluing_value(6, false), 1.0, 1e-15);
  EXPECT_EQ(vertex_gluing_value(2, true), 0.0);
  EXPECT_NEAR(vertex_gluing_value(3, true), 1.0, 1e-15);
  // The paper's example: a(t) = -d0(t) = 4t² - 1 on [0,1/2], 0 on [1/2,1].
  const SplitGluing a = SplitGluing::symmetric(-1.0, 0.0, Blending::q0);
  for (double t : {0.0, 0.2, 0.49}) EXPECT_NEAR(a.eval(t), 4 * t * t - 1, 1e-15);
  for (double t : {0.5, 0.8, 1.0}) EXPECT_EQ(a.eval(t), 0.0);
  for (Blending bl : {Blending::q0, Blending::q1, Blending::c1}) {
    const SplitGluing g = SplitGluing::symmetric(0.618, -1.0, bl);
    EXPECT_NEAR(g.eval(0.0), 0.618, 1e-15);
    EXPECT_NEAR(g.eval(1.0), 1.0, 1e-15);  // a(1) = -A1
    EXPECT_NEAR(g.eval(0.0, 1, 0), 0.0, 1e-14);
    EXPECT_NEAR(g.eval(1.0, 1, 1), 0.0, 1e-14);
    const SplitGluing r = g.reversed();
    for (double t : {0.1, 0.4, 0.6, 0.9}) EXPECT_NEAR(r.eval(t), -g.eval(1 - t), 1e-14);
    if (bl != Blending::q0) EXPECT_NEAR(g.eval(0.5, 1, 0), g.eval(0.5, 1, 1), 1e-13);  // C1 at 1/2
    // Restriction to the halves (nested refinement).
    const SplitGluing left = g.restricted(0.0, 0.5), back = g.restricted(0.5, 0.0);
    for (double s : {0.0, 0.3, 1.0}) {
      EXPECT_NEAR(left.eval(s), g.eval(0.5 * s, 0, 0), 1e-14);
      EXPECT_NEAR(back.eval(s), -g.eval(0.5 - 0.5 * s, 0, 0), 1e-14);
    }
  }
}

}  // namespace
}  // namespace iga
