/// @file
/// Exactness, positivity and symmetry of the quadrature rules in quadrature/.

#include "quadrature/quadrature_rule.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace iga {
namespace {

/// P_n(2x - 1), the Legendre polynomial shifted to [0,1].
double shifted_legendre(int n, double x) {
  const double t = 2.0 * x - 1.0;
  double p0 = 1.0, p1 = t;
  if (n == 0) return 1.0;
  for (int k = 2; k <= n; ++k) {
    const double p2 = ((2 * k - 1) * t * p1 - (k - 1) * p0) / k;
    p0 = p1;
    p1 = p2;
  }
  return p1;
}

/// Exact integral of x^i y^j over the unit triangle: i! j! / (i + j + 2)!.
double triangle_monomial_integral(int i, int j) {
  double v = 1.0;
  // i! j! / (i+j+2)! = prod_{k=1..j} k / (i + k) / ((i + j + 1)(i + j + 2))
  for (int k = 1; k <= j; ++k) v *= static_cast<double>(k) / (i + k);
  return v / ((i + j + 1.0) * (i + j + 2.0));
}

double integrate(const QuadratureRule& rule, int i, int j) {
  double s = 0.0;
  for (int k = 0; k < rule.size(); ++k)
    s += rule.weights[k] * std::pow(rule.points[k].x(), i) * std::pow(rule.points[k].y(), j);
  return s;
}

double weight_sum(const QuadratureRule& rule) { return std::accumulate(rule.weights.begin(), rule.weights.end(), 0.0); }

/// Worst relative error over all monomials x^i y^j with i + j <= d on the unit triangle.
double triangle_exactness_error(const QuadratureRule& rule, int d) {
  double worst = 0.0;
  for (int i = 0; i <= d; ++i)
    for (int j = 0; i + j <= d; ++j) {
      const double exact = triangle_monomial_integral(i, j);
      worst = std::max(worst, std::abs(integrate(rule, i, j) - exact) / exact);
    }
  return worst;
}

/// Checks positivity, strict interiority and invariance of the point set (with weights) under the
/// six permutations of barycentric coordinates.
void expect_symmetric_positive_interior(const QuadratureRule& rule, int d) {
  for (int k = 0; k < rule.size(); ++k) {
    const Point2& p = rule.points[k];
    EXPECT_GT(rule.weights[k], 0.0) << "degree " << d << " point " << k;
    EXPECT_GT(p.x(), 0.0) << "degree " << d;
    EXPECT_GT(p.y(), 0.0) << "degree " << d;
    EXPECT_LT(p.x() + p.y(), 1.0) << "degree " << d;
  }
  static constexpr int perm[6][2] = {{1, 2}, {2, 1}, {0, 1}, {1, 0}, {0, 2}, {2, 0}};
  for (int k = 0; k < rule.size(); ++k) {
    const Point2& p = rule.points[k];
    const std::array<double, 3> l = {1.0 - p.x() - p.y(), p.x(), p.y()};
    for (const auto& s : perm) {
      const Point2 image(l[s[0]], l[s[1]]);
      int matches = 0;
      for (int m = 0; m < rule.size(); ++m) {
        if ((rule.points[m] - image).norm() < 1e-13) {
          ++matches;
          EXPECT_NEAR(rule.weights[m], rule.weights[k], 1e-15) << "degree " << d;
        }
      }
      EXPECT_EQ(matches, 1) << "degree " << d << " point " << k;
    }
  }
}

TEST(QuadratureGauss, ExactForMonomialsUpTo2nMinus1) {
  for (int n = 1; n <= 30; ++n) {
    const QuadratureRule rule = gauss_legendre(n);
    ASSERT_EQ(rule.size(), n);
    EXPECT_EQ(rule.degree, 2 * n - 1);
    for (int k = 0; k <= 2 * n - 1; ++k) {
      double s = 0.0;
      for (int q = 0; q < n; ++q) s += rule.weights[q] * std::pow(rule.points[q].x(), k);
      EXPECT_NEAR(s, 1.0 / (k + 1), 1e-14 / (k + 1)) << "n=" << n << " k=" << k;
    }
  }
}

TEST(QuadratureGauss, PointsInsideSortedSymmetricYZero) {
  for (int n = 1; n <= 60; ++n) {
    const QuadratureRule rule = gauss_legendre(n);
    for (int q = 0; q < n; ++q) {
      EXPECT_GT(rule.points[q].x(), 0.0);
      EXPECT_LT(rule.points[q].x(), 1.0);
      EXPECT_EQ(rule.points[q].y(), 0.0);
      EXPECT_GT(rule.weights[q], 0.0);
      EXPECT_NEAR(rule.points[q].x(), 1.0 - rule.points[n - 1 - q].x(), 2e-16);
      if (q > 0) {
        EXPECT_LT(rule.points[q - 1].x(), rule.points[q].x());
      }
    }
    EXPECT_NEAR(weight_sum(rule), 1.0, 1e-14);
  }
  EXPECT_DOUBLE_EQ(gauss_legendre(1).points[0].x(), 0.5);
  EXPECT_DOUBLE_EQ(gauss_legendre(1).weights[0], 1.0);
  EXPECT_NEAR(gauss_legendre(2).points[0].x(), 0.5 - 0.5 / std::sqrt(3.0), 1e-16);
  EXPECT_NEAR(gauss_legendre(3).weights[1], 4.0 / 9.0, 1e-16);
}

TEST(QuadratureGauss, OrthogonalityOfLegendrePolynomialsUpToN60) {
  // Points are the roots of P_n, so P_n^2 (degree 2n) integrates to 0 instead of 1/(2n+1):
  // the rule is not exact at degree 2n. Products P_a P_b with a + b <= 2n-1 are integrated exactly.
  for (int n = 1; n <= 60; ++n) {
    const QuadratureRule rule = gauss_legendre(n);
    double pn2 = 0.0;
    for (int q = 0; q < n; ++q) pn2 += rule.weights[q] * std::pow(shifted_legendre(n, rule.points[q].x()), 2);
    EXPECT_LT(std::abs(pn2), 1e-13) << "n=" << n;
    EXPECT_GT(std::abs(pn2 - 1.0 / (2 * n + 1)), 0.5 / (2 * n + 1)) << "n=" << n;
    for (int a = 0; a < n; ++a)
      for (int b = a; b <= std::min(n, 2 * n - 1 - a); ++b) {
        double s = 0.0;
        for (int q = 0; q < n; ++q)
          s += rule.weights[q] * shifted_legendre(a, rule.points[q].x()) * shifted_legendre(b, rule.points[q].x());
        EXPECT_NEAR(s, a == b ? 1.0 / (2 * a + 1) : 0.0, 1e-14) << "n=" << n << " a=" << a << " b=" << b;
      }
  }
}

TEST(QuadratureGauss, NotExactAtDegree2nForSmallN) {
  // Error of x^(2n): (n!)^4 / ((2n+1) ((2n)!)^2); visible in double for small n.
  for (int n = 1; n <= 6; ++n) {
    const QuadratureRule rule = gauss_legendre(n);
    double s = 0.0;
    for (int q = 0; q < n; ++q) s += rule.weights[q] * std::pow(rule.points[q].x(), 2 * n);
    double nf = std::tgamma(n + 1.0), n2f = std::tgamma(2.0 * n + 1.0);
    const double expected_error = std::pow(nf, 4) / ((2 * n + 1) * n2f * n2f);
    EXPECT_NEAR(1.0 / (2 * n + 1) - s, expected_error, 1e-12 * expected_error + 1e-16) << "n=" << n;
  }
}

TEST(QuadratureGauss, ForDegreeAndInvalidInput) {
  EXPECT_EQ(gauss_legendre_for_degree(-3).size(), 1);
  EXPECT_EQ(gauss_legendre_for_degree(0).size(), 1);
  EXPECT_EQ(gauss_legendre_for_degree(1).size(), 1);
  EXPECT_EQ(gauss_legendre_for_degree(2).size(), 2);
  EXPECT_EQ(gauss_legendre_for_degree(3).size(), 2);
  EXPECT_EQ(gauss_legendre_for_degree(4).size(), 3);
  EXPECT_EQ(gauss_legendre_for_degree(59).size(), 30);
  EXPECT_EQ(gauss_legendre_for_degree(60).size(), 31);
  EXPECT_THROW(gauss_legendre(0), std::invalid_argument);
  EXPECT_THROW(gauss_legendre(-1), std::invalid_argument);
}

TEST(QuadratureTensor, ExactForProductMonomials) {
  for (int d = 0; d <= 15; ++d) {
    const QuadratureRule rule = tensor_gauss(d);
    const int n = d / 2 + 1;
    ASSERT_EQ(rule.size(), n * n);
    EXPECT_GE(rule.degree, d);
    EXPECT_NEAR(weight_sum(rule), 1.0, 1e-14);
    for (int i = 0; i <= rule.degree; ++i)
      for (int j = 0; j <= rule.degree; ++j) {
        const double exact = 1.0 / ((i + 1.0) * (j + 1.0));
        EXPECT_NEAR(integrate(rule, i, j), exact, 1e-14 * exact) << "d=" << d << " i=" << i << " j=" << j;
      }
    // Not exact beyond the achieved degree in one variable.
    const int e = rule.degree + 1;
    EXPECT_GT(std::abs(integrate(rule, e, 0) - 1.0 / (e + 1)), 1e-12) << "d=" << d;
  }
}

TEST(QuadratureTriangle, CollapsedFallbackExactSymmetricUpTo25) {
  for (int d = 0; d <= 25; ++d) {
    const QuadratureRule rule = triangle_rule_collapsed(d);
    EXPECT_EQ(rule.degree, d);
    EXPECT_NEAR(weight_sum(rule), 0.5, 1e-15);
    EXPECT_LT(triangle_exactness_error(rule, d), 1e-14) << "d=" << d;
    expect_symmetric_positive_interior(rule, d);
  }
}

TEST(QuadratureTriangle, ExactSymmetricPositiveInteriorUpTo25) {
  for (int d = 0; d <= 25; ++d) {
    const QuadratureRule rule = triangle_rule(d);
    EXPECT_GE(rule.degree, d);
    EXPECT_NEAR(weight_sum(rule), 0.5, 1e-15);
    EXPECT_LT(triangle_exactness_error(rule, d), 1e-14) << "d=" << d << " size " << rule.size();
    expect_symmetric_positive_interior(rule, d);
  }
  EXPECT_EQ(triangle_rule(-2).degree, triangle_rule(0).degree);
}

TEST(QuadratureTriangle, HighDegreeFallbackStaysExact) {
  for (int d : {30, 40}) {
    const QuadratureRule rule = triangle_rule(d);
    EXPECT_GE(rule.degree, d);
    EXPECT_LT(triangle_exactness_error(rule, d), 1e-13) << "d=" << d;
  }
}

TEST(QuadratureTriangle, CompactRulesCoverDegreesUpTo20) {
  // Point counts of the generated tables (quadrature/tools/generate_triangle_rules.cc); a
  // regenerated table may only shrink them.
  const int max_points[21] = {1, 1, 3, 6, 6, 7, 12, 15, 16, 19, 25, 28, 33, 37, 42, 49, 58, 63, 72, 76, 90};
  for (int d = 0; d <= 20; ++d) {
    EXPECT_GT(triangle_rule_tabulated(d).size(), 0) << "d=" << d;
    EXPECT_LE(triangle_rule(d).size(), max_points[d]) << "d=" << d;
  }
  EXPECT_EQ(triangle_rule_tabulated(21).size(), 0);  // beyond the tables: the collapsed fallback
  EXPECT_EQ(triangle_rule(21).size(), triangle_rule_collapsed(21).size());
}

TEST(QuadratureTriangle, TabulatedRulesAreCompact) {
  // Every tabulated rule must beat the fallback of the same degree and be exact for its degree.
  for (int d = 0; d <= 25; ++d) {
    const QuadratureRule tab = triangle_rule_tabulated(d);
    if (tab.size() == 0) continue;
    EXPECT_GE(tab.degree, d);
    EXPECT_LT(tab.size(), triangle_rule_collapsed(d).size()) << "d=" << d;
    EXPECT_LT(triangle_exactness_error(tab, tab.degree), 1e-14) << "d=" << d;
  }
}

TEST(QuadratureSubcell, SplitTriangleAtCentroidIntegratesExactly) {
  // f(x, y) = 1 + 2x - y + 3x^2 y + x y^3 - 5 y^4 over the triangle (0.2,0.1), (1.7,0.4), (0.5,1.9),
  // split into three sub-triangles at its centroid. Exact value via the affine map and monomials.
  const Point2 a(0.2, 0.1), b(1.7, 0.4), c(0.5, 1.9);
  const Point2 g = (a + b + c) / 3.0;
  auto f = [](const Point2& p) {
    const double x = p.x(), y = p.y();
    return 1 + 2 * x - y + 3 * x * x * y + x * y * y * y - 5 * std::pow(y, 4);
  };
  // Reference: a direct degree-4 rule on the whole triangle is exact for f.
  const QuadratureRule whole = map_to_triangle(triangle_rule(4), a, b, c);
  const QuadratureRule ref = triangle_rule(4);
  const QuadratureRule split =
      concatenate({map_to_triangle(ref, a, b, g), map_to_triangle(ref, b, c, g), map_to_triangle(ref, c, a, g)});
  EXPECT_EQ(split.size(), 3 * ref.size());
  EXPECT_EQ(split.degree, ref.degree);
  const double area = 0.5 * std::abs((b - a).x() * (c - a).y() - (b - a).y() * (c - a).x());
  EXPECT_NEAR(weight_sum(whole), area, 1e-14);
  EXPECT_NEAR(weight_sum(split), area, 1e-14);
  double i_whole = 0.0, i_split = 0.0;
  for (int k = 0; k < whole.size(); ++k) i_whole += whole.weights[k] * f(whole.points[k]);
  for (int k = 0; k < split.size(); ++k) i_split += split.weights[k] * f(split.points[k]);
  // Independent exact value: Duffy-collapsed high-order tensor rule on the same triangle.
  const QuadratureRule dense = map_to_triangle(triangle_rule_collapsed(10), a, b, c);
  double i_dense = 0.0;
  for (int k = 0; k < dense.size(); ++k) i_dense += dense.weights[k] * f(dense.points[k]);
  EXPECT_NEAR(i_whole, i_dense, 1e-13 * std::abs(i_dense));
  EXPECT_NEAR(i_split, i_dense, 1e-13 * std::abs(i_dense));
}

TEST(QuadratureSubcell, MonomialsOverSplitUnitTriangle) {
  // Unit triangle split at its centroid, with clockwise sub-triangles to check orientation handling.
  const Point2 a(0, 0), b(1, 0), c(0, 1), g(1.0 / 3, 1.0 / 3);
  for (int d = 0; d <= 12; ++d) {
    const QuadratureRule ref = triangle_rule(d);
    const QuadratureRule split =
        concatenate({map_to_triangle(ref, a, b, g), map_to_triangle(ref, g, c, b), map_to_triangle(ref, c, a, g)});
    EXPECT_NEAR(weight_sum(split), 0.5, 1e-15);
    EXPECT_LT(triangle_exactness_error(split, d), 2e-14) << "d=" << d;
  }
}

TEST(QuadratureSubcell, BoxSplitIntoFourAndMixedConcatenation) {
  // [-1, 2] x [0.5, 1.5] split into 4 boxes; integrate x^i y^j exactly.
  const QuadratureRule ref = tensor_gauss(5);
  std::vector<QuadratureRule> parts;
  for (double x0 : {-1.0, 0.5})
    for (double y0 : {0.5, 1.0}) parts.push_back(map_to_box(ref, Point2(x0, y0), Point2(x0 + 1.5, y0 + 0.5)));
  const QuadratureRule box = concatenate(parts);
  EXPECT_EQ(box.size(), 4 * ref.size());
  EXPECT_NEAR(weight_sum(box), 3.0, 1e-14);
  for (int i = 0; i <= 5; ++i)
    for (int j = 0; j <= 5; ++j) {
      const double exact = (std::pow(2.0, i + 1) - std::pow(-1.0, i + 1)) / (i + 1) *
                           (std::pow(1.5, j + 1) - std::pow(0.5, j + 1)) / (j + 1);
      EXPECT_NEAR(integrate(box, i, j), exact, 1e-13 * std::max(1.0, std::abs(exact))) << i << " " << j;
    }
  // Degree of a concatenation is the smallest part degree.
  const QuadratureRule mixed = concatenate({triangle_rule(7), triangle_rule(3), tensor_gauss(9)});
  EXPECT_EQ(mixed.degree, std::min({triangle_rule(7).degree, triangle_rule(3).degree, tensor_gauss(9).degree}));
  EXPECT_EQ(concatenate({}).size(), 0);
}

}  // namespace
}  // namespace iga
