/// @file
/// The 51 WS4 simplex splines on the reference triangle against the WS4 notes (§5–§7, §12):
/// partition of unity, nonnegativity, integrals, values at (0.31, 0.17), edge traces, C³ across
/// split lines, the collocation matrix A = [ρ_j(B_i)] of §6, and the Marsden identity.

#include "spaces/ws4/ws4_basis.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <random>
#include <string>

#include "spaces/bspline/bspline_basis_1d.hpp"
#include "spaces/bspline/knot_vector.hpp"
#include "spaces/ws4/ws4_collocation.hpp"
#include "spaces/ws4/ws4_knots.hpp"

namespace iga::ws4 {
namespace {

const Ws4Basis& basis() { return Ws4Basis::reference(); }

std::vector<Point2> random_points(int n, unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Point2> pts;
  while (static_cast<int>(pts.size()) < n) {
    Point2 x(u(gen), u(gen));
    if (x.sum() > 1.0) x = Point2(1.0 - x.x(), 1.0 - x.y());
    pts.push_back(x);
  }
  return pts;
}

/// Reference coordinates of the labelled points of the notes.
Point2 pt(const std::string& label) {
  static const std::map<std::string, Point2> p = {
      {"p1", {0, 0}},        {"p2", {1, 0}},        {"p3", {0, 1}},        {"q31", {0.25, 0}},
      {"q3", {0.5, 0}},      {"q32", {0.75, 0}},    {"q12", {0.75, 0.25}}, {"q1", {0.5, 0.5}},
      {"q13", {0.25, 0.75}}, {"q21", {0, 0.25}},    {"q2", {0, 0.5}},      {"q23", {0, 0.75}},
      {"v3", {0.375, 0.25}}, {"v1", {0.375, 0.375}}, {"v2", {0.25, 0.375}},
      {"u1", {3.0 / 7, 3.0 / 7}}, {"u2", {1.0 / 7, 3.0 / 7}}, {"u3", {3.0 / 7, 1.0 / 7}},
      {"w1", {0.5, 1.0 / 6}},     {"w2", {1.0 / 6, 0.5}},     {"w3", {1.0 / 3, 0.5}},
      {"w4", {1.0 / 3, 1.0 / 6}}, {"w5", {1.0 / 6, 1.0 / 3}}, {"w6", {0.5, 1.0 / 3}}};
  return p.at(label);
}

/// The functional ρ_j (j = 1..51) of §2.2: a point and the derivative directions b - a of D_{ab}.
struct Functional {
  Point2 x;
  std::vector<Point2> dirs;
};
Functional rho(int j) {
  // Return a Point2, not the Eigen expression: that would refer to the two temporaries pt(b) and
  // pt(a), which die when the lambda returns (garbage derivatives in unoptimised builds).
  auto D = [](const char* a, const char* b) -> Point2 { return pt(b) - pt(a); };
  static const char* vert[6][3] = {{"p1", "p1", "p2"}, {"p1", "p1", "p3"}, {"p2", "p2", "p3"},
                                   {"p2", "p2", "p1"}, {"p3", "p3", "p1"}, {"p3", "p3", "p2"}};
  if (j <= 3) return {pt(j == 1 ? "p1" : j == 2 ? "p2" : "p3"), {}};
  if (j <= 24 && !(j >= 16 && j <= 18)) {  // pure edge derivatives of order 1, 2, 3
    const int order = j <= 9 ? 1 : (j <= 15 ? 2 : 3);
    const int k = (j <= 9 ? j - 4 : (j <= 15 ? j - 10 : j - 19));
    return {pt(vert[k][0]), std::vector<Point2>(order, D(vert[k][1], vert[k][2]))};
  }
  if (j <= 18) {
    static const char* m[3][3] = {{"p1", "p2", "p3"}, {"p2", "p3", "p1"}, {"p3", "p1", "p2"}};
    const auto& s = m[j - 16];
    return {pt(s[0]), {D(s[0], s[1]), D(s[0], s[2])}};
  }
  if (j <= 30) {  // D²_{ab} D_{ac} at a
    static const char* m[6][3] = {{"p1", "p2", "p3"}, {"p1", "p3", "p2"}, {"p2", "p3", "p1"},
                                  {"p2", "p1", "p3"}, {"p3", "p1", "p2"}, {"p3", "p2", "p1"}};
    const auto& s = m[j - 25];
    return {pt(s[0]), {D(s[0], s[1]), D(s[0], s[1]), D(s[0], s[2])}};
  }
  if (j <= 33) {
    static const char* m[3][2] = {{"q3", "p3"}, {"q1", "p1"}, {"q2", "p2"}};
    return {pt(m[j - 31][0]), {D(m[j - 31][0], m[j - 31][1])}};
  }
  if (j <= 45) {
    static const char* m[6][2] = {{"q31", "p3"}, {"q21", "p2"}, {"q12", "p1"},
                                  {"q32", "p3"}, {"q23", "p2"}, {"q13", "p1"}};
    const auto& s = m[(j - 34) % 6];
    return {pt(s[0]), std::vector<Point2>(j <= 39 ? 2 : 3, D(s[0], s[1]))};
  }
  if (j <= 48) {
    static const char* m[3][2] = {{"q3", "p3"}, {"q1", "p1"}, {"q2", "p2"}};
    return {pt(m[j - 46][0]), std::vector<Point2>(3, D(m[j - 46][0], m[j - 46][1]))};
  }
  return {pt(j == 49 ? "v3" : j == 50 ? "v1" : "v2"), {}};
}

TEST(Ws4Basis, PartitionOfUnityAndNonnegativity) {
  std::vector<Point2> pts = random_points(3000, 11);
  for (const SplitRegion& r : basis().split().regions()) pts.push_back(r.centroid);
  ReferenceDerivatives t;
  basis().tabulate(pts, t);
  for (int k = 0; k < static_cast<int>(pts.size()); ++k) {
    EXPECT_NEAR(t.value.col(k).sum(), 1.0, 1e-14);
    EXPECT_NEAR(t.dxi.col(k).sum(), 0.0, 1e-11);
    EXPECT_NEAR(t.dxixi.col(k).sum(), 0.0, 1e-9);
    EXPECT_GE(t.value.col(k).minCoeff(), -1e-15);
  }
}

TEST(Ws4Basis, IntegralsAreWeightsAndSupportsMatchTheNotes) {
  const QuadratureRule rule = basis().split().composite_rule(4);
  ReferenceDerivatives t;
  basis().tabulate(rule.points, t);
  const Eigen::VectorXd w = Eigen::Map<const Eigen::VectorXd>(rule.weights.data(), rule.size());
  const Eigen::VectorXd integrals = t.value * w;
  for (int i = 0; i < Ws4Basis::size; ++i)
    EXPECT_NEAR(integrals(i), ws4_knot_sets()[i].c * 0.5 / 480, 1e-15) << "B" << i + 1;
  // Number of regions where B_i is not identically zero, per type (§5).
  const int representative[11] = {0, 3, 9, 15, 18, 24, 30, 33, 39, 45, 48};
  const int support[11] = {4, 18, 36, 54, 60, 91, 110, 157, 180, 212, 190};
  for (int k = 0; k < 11; ++k) {
    int n = 0;
    for (int r = 0; r < static_cast<int>(basis().split().regions().size()); ++r)
      n += !basis().piece(r, representative[k]).is_zero();
    EXPECT_EQ(n, support[k]) << "B" << representative[k] + 1;
  }
}

TEST(Ws4Basis, ValuesAndDerivativesAtTheReferencePointOfTheNotes) {
  struct Row {
    int i;
    double v[6];
  };
  const Row rows[] = {
      {16, {1.024e-05, -0.002048, -0.002048, 0.3072, 0.3072, 0.3072}},
      {19, {1.0666666666667e-07, -4.2666666666667e-05, -0.00017066666666667, 0.0128, 0.0512, 0.2048}},
      {25, {0.033287697777778, -0.71425422222222, -1.0744533333333, 10.760533333333, 16.6016, 25.3632}},
      {26, {0.0049442311111111, -0.25341866666667, -0.16689777777778, 9.2352, 5.8496, 3.5925333333333}},
      {31, {0.024466524444444, 9.9555555555556e-05, -1.2229404444444, -0.029866666666667, -0.11946666666667, 45.397333333333}},
      {34, {0.324769568, -0.5311744, -3.2440192, -21.82656, -15.67488, -29.91744}},
      {35, {0.03973456, -0.868928, -0.036224, 7.776, -6.6432, -8.064}},
      {37, {0.072642794666667, 0.88587093333333, -0.19938986666667, 5.68064, -11.20768, -35.95264}},
      {38, {1.3333333333333e-05, -0.0021333333333333, 0.0010666666666667, 0.256, -0.128, 0.064}},
      {40, {0.14647671466667, -0.46400284444444, 0.66924657777778, -11.38176, -0.72021333333333, -21.215573333333}},
      {41, {0.046962346666667, -0.65857422222222, 0.35848533333333, 2.6026666666667, -7.4581333333333, -2.6368}},
      {43, {0.010253639111111, 0.25677937777778, 0.48233813333333, 4.4219733333333, 7.50592, 10.99776}},
      {44, {0.0059303822222222, 0.0014222222222222, 0.13903644444444, -0.17066666666667, 0.085333333333333, 2.4234666666667}},
      {46, {0.023335373333333, 0.312032, 0.43893866666667, 0.288, 5.4048, 5.8384}},
      {47, {0.049128170666667, 0.23971413333333, 0.88076373333333, -5.96608, 2.52416, 7.02848}},
      {48, {0.0059725573333333, 0.15614613333333, 0.3064384, 2.98912, 5.72736, 10.70208}},
      {49, {0.17363556, 1.7991786666667, 1.9483893333333, -1.0752, 4.0544, -19.5088}},
      {51, {0.0384362, -0.15666666666667, 0.72144, -3.88, -6.16, 5.376}},
  };
  ReferenceDerivatives t;
  basis().tabulate({Point2(0.31, 0.17)}, t);
  std::vector<bool> listed(Ws4Basis::size, false);
  for (const Row& row : rows) {
    const int i = row.i - 1;
    listed[i] = true;
    const double got[6] = {t.value(i, 0), t.dxi(i, 0), t.deta(i, 0), t.dxixi(i, 0), t.dxieta(i, 0), t.detaeta(i, 0)};
    for (int c = 0; c < 6; ++c)
      EXPECT_NEAR(got[c], row.v[c], 1e-12 * std::max(1.0, std::abs(row.v[c]))) << "B" << row.i << " column " << c;
  }
  for (int i = 0; i < Ws4Basis::size; ++i)
    if (!listed[i]) EXPECT_EQ(t.value(i, 0), 0.0) << "B" << i + 1;
  // Exact rationals of §12.
  EXPECT_NEAR(t.value(15, 0), 4.0 / 390625, 1e-17);
  EXPECT_NEAR(t.value(24, 0), 1872433.0 / 56250000, 1e-15);
  EXPECT_NEAR(t.value(33, 0), 10149049.0 / 31250000, 1e-15);
  EXPECT_NEAR(t.value(48, 0), 4340889.0 / 25000000, 1e-15);
}

TEST(Ws4Basis, ClosedFormOfB1) {
  // B1 = (λ1 − 3λ2 − 3λ3)⁴ on {λ1 ≥ 3/4}, 0 elsewhere.
  for (const Point2& x : random_points(500, 5)) {
    ReferenceDerivatives t;
    basis().tabulate({x}, t);
    const double l1 = 1.0 - x.sum();
    const double expected = l1 >= 0.75 ? std::pow(l1 - 3 * x.x() - 3 * x.y(), 4) : 0.0;
    EXPECT_NEAR(t.value(0, 0), expected, 1e-15);
  }
}

TEST(Ws4Basis, EdgeTracesAreUnivariateQuarticBSplines) {
  const KnotVector kv(4, {0, 0, 0, 0, 0, 0.25, 0.5, 0.75, 1, 1, 1, 1, 1});
  // Functions nonzero on each edge, in order from its first to its last point (§5).
  const int on_edge[3][8] = {{1, 4, 10, 19, 22, 13, 7, 2}, {2, 6, 12, 21, 24, 15, 9, 3}, {1, 5, 11, 20, 23, 14, 8, 3}};
  const Point2 from[3] = {pt("p1"), pt("p2"), pt("p1")}, to[3] = {pt("p2"), pt("p3"), pt("p3")};
  for (int e = 0; e < 3; ++e)
    for (int s = 0; s <= 40; ++s) {
      const double u = (s + 0.37) / 41.5;
      ReferenceDerivatives t;
      basis().tabulate({from[e] + u * (to[e] - from[e])}, t);
      const int span = kv.find_span(u);
      const Eigen::MatrixXd n = bspline_derivatives(kv, span, u, 0);
      Eigen::VectorXd expected = Eigen::VectorXd::Zero(Ws4Basis::size);
      for (int j = 0; j <= 4; ++j) expected(on_edge[e][span - 4 + j] - 1) = n(0, j);
      EXPECT_LT((t.value.col(0) - expected).cwiseAbs().maxCoeff(), 1e-14) << "edge " << e << " u " << u;
    }
}

TEST(Ws4Basis, C3AcrossEveryInteriorSplitSegment) {
  const Ws4Split& s = basis().split();
  // Regions on each side of a segment: the two regions having it as a boundary edge.
  std::map<std::pair<int, int>, std::vector<int>> sides;
  for (int r = 0; r < static_cast<int>(s.regions().size()); ++r) {
    const auto& v = s.regions()[r].vertices;
    for (size_t k = 0; k < v.size(); ++k) {
      const int a = v[k], b = v[(k + 1) % v.size()];
      sides[{std::min(a, b), std::max(a, b)}].push_back(r);
    }
  }
  int interior = 0;
  double max_jump3 = 0.0, max_jump4 = 0.0;
  for (const auto& [seg, regs] : sides) {
    if (regs.size() != 2) continue;
    ++interior;
    const Point2 m = 0.5 * (s.vertex_point(seg.first) + s.vertex_point(seg.second));
    for (int i = 0; i < Ws4Basis::size; ++i) {
      // All partial derivatives ∂x^a ∂y^b with a + b <= 4 of the two pieces at m.
      for (int a = 0; a <= 4; ++a)
        for (int b = 0; a + b <= 4; ++b) {
          double v[2];
          for (int side = 0; side < 2; ++side) {
            Poly4 d = basis().piece(regs[side], i);
            for (int k = 0; k < a; ++k) d = d.derivative(0);
            for (int k = 0; k < b; ++k) d = d.derivative(1);
            v[side] = d(m - basis().center(regs[side]));
          }
          const double j = std::abs(v[0] - v[1]);
          (a + b <= 3 ? max_jump3 : max_jump4) = std::max(a + b <= 3 ? max_jump3 : max_jump4, j);
        }
    }
  }
  std::cout << "interior segments " << interior << ", max jump of derivatives of order <= 3: " << max_jump3
            << ", of order 4: " << max_jump4 << "\n";
  EXPECT_EQ(interior, 417);
  EXPECT_LT(max_jump3, 1e-8);  // third derivatives of the pieces are O(1e4)
  EXPECT_GT(max_jump4, 1.0);   // the 4th derivative does jump: C³, not C⁴
}

TEST(Ws4Basis, CollocationMatrixMatchesTheNotes) {
  const Eigen::MatrixXd expected = ws4_collocation_matrix();  // (j, i) = ρ_j(B_i), the table of §6
  Eigen::MatrixXd got(51, 51);
  for (int j = 1; j <= 51; ++j) {
    const Functional f = rho(j);
    double buf[51];
    basis().directional_derivatives(f.x, f.dirs, buf);
    for (int i = 0; i < 51; ++i) got(j - 1, i) = buf[i];
  }
  double worst = 0.0;
  for (int j = 0; j < 51; ++j)
    for (int i = 0; i < 51; ++i)
      worst = std::max(worst, std::abs(got(j, i) - expected(j, i)) / std::max(1.0, std::abs(expected(j, i))));
  std::cout << "collocation matrix: worst relative deviation from §6 " << worst << "\n";
  EXPECT_LT(worst, 1e-12);
  // Σ_i ρ_j(B_i) = ρ_j(1).
  for (int j = 0; j < 51; ++j) {
    const bool value = j < 3 || j >= 48;
    EXPECT_NEAR(got.row(j).sum(), value ? 1.0 : 0.0, 1e-9) << "ρ" << j + 1;
  }
}

TEST(Ws4Basis, MarsdenIdentityReproducesQuartics) {
  static const char* dual[48][4] = {
      {"p1", "p1", "p1", "p1"},    {"p2", "p2", "p2", "p2"},    {"p3", "p3", "p3", "p3"},
      {"p1", "p1", "p1", "q31"},   {"p1", "p1", "p1", "q21"},   {"p2", "p2", "p2", "q12"},
      {"p2", "p2", "p2", "q32"},   {"p3", "p3", "p3", "q23"},   {"p3", "p3", "p3", "q13"},
      {"p1", "p1", "q31", "q3"},   {"p1", "p1", "q21", "q2"},   {"p2", "p2", "q12", "q1"},
      {"p2", "p2", "q32", "q3"},   {"p3", "p3", "q23", "q2"},   {"p3", "p3", "q13", "q1"},
      {"p1", "p1", "q31", "q21"},  {"p2", "p2", "q32", "q12"},  {"p3", "p3", "q13", "q23"},
      {"p1", "q3", "q31", "q32"},  {"p1", "q2", "q23", "q21"},  {"p2", "q1", "q12", "q13"},
      {"p2", "q3", "q31", "q32"},  {"p3", "q2", "q23", "q21"},  {"p3", "q1", "q12", "q13"},
      {"p1", "q3", "q31", "q21"},  {"p1", "q2", "q31", "q21"},  {"p2", "q1", "q32", "q12"},
      {"p2", "q3", "q32", "q12"},  {"p3", "q2", "q13", "q23"},  {"p3", "q1", "q13", "q23"},
      {"q3", "q31", "q32", "u3"},  {"q1", "q12", "q13", "u1"},  {"q2", "q23", "q21", "u2"},
      {"q3", "q31", "q21", "w1"},  {"q2", "q31", "q21", "w2"},  {"q1", "q32", "q12", "w3"},
      {"q3", "q32", "q12", "w4"},  {"q2", "q13", "q23", "w5"},  {"q1", "q13", "q23", "w6"},
      {"q2", "q31", "q21", "q3"},  {"q2", "q31", "q21", "q3"},  {"q1", "q32", "q12", "q3"},
      {"q1", "q32", "q12", "q3"},  {"q1", "q13", "q23", "q2"},  {"q1", "q13", "q23", "q2"},
      {"p3", "q1", "q2", "q3"},    {"p1", "q1", "q2", "q3"},    {"p2", "q1", "q2", "q3"}};
  // σ: p1 -> p2 -> p3 -> p1 on the labels of ψ49.
  const std::map<std::string, std::string> sigma = {{"q3", "q1"},   {"q1", "q2"},   {"q2", "q3"},
                                                    {"q31", "q12"}, {"q32", "q13"}, {"q12", "q23"},
                                                    {"q13", "q21"}, {"q21", "q32"}, {"q23", "q31"}};
  std::mt19937 gen(3);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  for (int trial = 0; trial < 20; ++trial) {
    const Point2 y(u(gen), u(gen));
    auto Q = [&](const std::string& label) { return 1.0 + y.dot(pt(label)); };
    std::vector<double> psi(51);
    for (int i = 0; i < 48; ++i) psi[i] = Q(dual[i][0]) * Q(dual[i][1]) * Q(dual[i][2]) * Q(dual[i][3]);
    for (int k = 0; k < 3; ++k) {
      auto L = [&](std::string s) {
        for (int r = 0; r < k; ++r) s = sigma.at(s);
        return Q(s);
      };
      const double q3 = L("q3"), q31 = L("q31"), q32 = L("q32"), q12 = L("q12"), q21 = L("q21"), q1 = L("q1"),
                   q2 = L("q2"), q13 = L("q13"), q23 = L("q23");
      psi[48 + k] = q3 * (-32.0 / 5 * q3 * q3 * q3 + 11.0 / 15 * q31 * q3 * q32 + 29.0 / 5 * (q3 * q32 * q12 + q3 * q31 * q21) -
                          59.0 / 15 * (q32 * q12 * q1 + q31 * q21 * q2) + 11.0 / 5 * (q12 * q1 * q13 + q21 * q2 * q23) -
                          11.0 / 15 * (q1 * q13 * q23 + q2 * q23 * q13));
    }
    const std::vector<Point2> xs = random_points(50, 100 + trial);
    ReferenceDerivatives t;
    basis().tabulate(xs, t);
    for (int k = 0; k < static_cast<int>(xs.size()); ++k) {
      double s = 0.0;
      for (int i = 0; i < 51; ++i) s += psi[i] * t.value(i, k);
      const double expected = std::pow(1.0 + y.dot(xs[k]), 4);
      EXPECT_NEAR(s, expected, 1e-12 * std::max(1.0, expected));
    }
  }
}

}  // namespace
}  // namespace iga::ws4
