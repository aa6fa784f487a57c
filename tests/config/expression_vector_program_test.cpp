// The compiled expression programs behind FunctionBatch (immediate constants, multiply-adds, Horner
// and factored forms of polynomials, shared fractional powers, reused work slots) against
// references whose error is known: long double evaluations of polynomials, std::pow, and the
// scalar muParser evaluation of the same functions.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "config/expression.hpp"

namespace iga {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

SymbolicFunction parse(const std::string& text) { return SymbolicFunction::parse(text, "test.yaml:1:1: f"); }

std::vector<SymbolicFunction> jet(const SymbolicFunction& u) {
  const SymbolicFunction ux = u.diff_x(), uy = u.diff_y();
  return {u, ux, uy, ux.diff_x(), ux.diff_y(), uy.diff_y()};
}

/// Points of the unit square on a skewed grid: two full blocks of 128 and a remainder of 3.
Eigen::Matrix2Xd unit_square_points(int count = 2 * 128 + 3) {
  Eigen::Matrix2Xd points(2, count);
  for (int k = 0; k < count; ++k) points.col(k) << std::fmod(0.618034 * k, 1.0), std::fmod(0.7548777 * k + 0.1, 1.0);
  return points;
}

/// A polynomial in one variable by its coefficients (lowest degree first).
struct Polynomial {
  std::vector<long double> c;

  Polynomial derivative() const {
    Polynomial d;
    for (size_t i = 1; i < c.size(); ++i) d.c.push_back(static_cast<long double>(i) * c[i]);
    return d;
  }
  long double operator()(long double t) const {
    long double v = 0;
    for (size_t i = c.size(); i-- > 0;) v = v * t + c[i];
    return v;
  }
  /// Σ |c_i|: on [0, 1] no form of the polynomial (expanded, Horner, factored into x, 1 - x, ...)
  /// has an intermediate value larger in magnitude.
  long double absolute_sum() const {
    long double s = 0;
    for (long double v : c) s += std::abs(v);
    return s;
  }
};

/// t^a (1 - t)^b expanded.
Polynomial bump(int a, int b) {
  Polynomial p;
  p.c.assign(a + b + 1, 0);
  long double binomial = 1;
  for (int j = 0; j <= b; ++j) {
    p.c[a + j] = (j % 2 ? -1 : 1) * binomial;
    binomial = binomial * (b - j) / (j + 1);
  }
  return p;
}

/// The i-th derivative.
Polynomial derivative(Polynomial p, int i) {
  while (i-- > 0) p = p.derivative();
  return p;
}

// u = X(x) Y(y) with X, Y bumps: the jet (factored derivatives, where the compiler tries the sum as
// written, factored and in Horner form) and Δ²u (which GiNaC returns expanded) against long double
// references. Every form the program or muParser may take makes fewer than 32 roundings along any
// path, on values bounded on the unit square by B = the sum of the absolute coefficients of the
// function's summands X^(i) Y^(j) (all |x|, |1-x|, |y|, |1-y| ≤ 1), so both stay within 64 eps B.
TEST(ExpressionVectorProgram, PolynomialJetsAndSourcesWithinRoundingBounds) {
  struct Case {
    const char* text;
    Polynomial x, y;
  };
  const std::vector<Case> cases = {{"x^2*(1-x)^2*y^2*(1-y)^2", bump(2, 2), bump(2, 2)},
                                   {"x^4*(1-x)^3*y^3*(1-y)^5", bump(4, 3), bump(3, 5)},
                                   {"x*(1-x)*y*(1-y)", bump(1, 1), bump(1, 1)}};
  const Eigen::Matrix2Xd points = unit_square_points();
  for (const Case& c : cases) {
    const SymbolicFunction u = parse(c.text);
    std::vector<SymbolicFunction> fs = jet(u);
    fs.push_back(u.bilaplacian());
    // (derivative orders in x, y) of each summand of each function, with weights: Δ²u = X''''Y + 2X''Y'' + XY''''.
    struct Term {
      int i, j;
      long double weight;
    };
    const std::vector<std::vector<Term>> terms = {{{0, 0, 1}}, {{1, 0, 1}}, {{0, 1, 1}}, {{2, 0, 1}},
                                                  {{1, 1, 1}}, {{0, 2, 1}}, {{4, 0, 1}, {2, 2, 2}, {0, 4, 1}}};
    const FunctionBatch batch(fs);
    Eigen::MatrixXd values;
    batch.evaluate(points, values);
    for (size_t f = 0; f < fs.size(); ++f) {
      long double bound = 0;
      for (const Term& t : terms[f])
        bound += t.weight * derivative(c.x, t.i).absolute_sum() * derivative(c.y, t.j).absolute_sum();
      for (int k = 0; k < points.cols(); ++k) {
        long double exact = 0;
        for (const Term& t : terms[f])
          exact += t.weight * derivative(c.x, t.i)(points(0, k)) * derivative(c.y, t.j)(points(1, k));
        const double tolerance = 64 * kEps * static_cast<double>(bound);
        EXPECT_NEAR(values(static_cast<int>(f), k), static_cast<double>(exact), tolerance)
            << c.text << ", function " << f << " at (" << points(0, k) << ", " << points(1, k) << ")";
        EXPECT_NEAR(fs[f](points.col(k)), static_cast<double>(exact), tolerance) << c.text << ", muParser " << f;
      }
    }
  }
}

// Powers of one base whose exponents differ by integers come from one pow and integer powers:
// b^n = b^f b^k or b^f / b^|k|. pow is within 4 ulp (glibc's vector bound), b^|k| by at most
// 2 |k| roundings, the product or quotient one more: within (5 + 2|k|) eps relative, |k| ≤ 4 here.
TEST(ExpressionVectorProgram, SharedFractionalPowersWithinUlps) {
  const std::vector<std::pair<std::string, double>> powers = {
      {"(1/3)", 1.0 / 3},   {"(-2/3)", -2.0 / 3}, {"(-5/3)", -5.0 / 3}, {"(-11/3)", -11.0 / 3},
      {"(7/3)", 7.0 / 3},   {"(1/2)", 0.5},       {"(-1/2)", -0.5},     {"(-5/2)", -2.5},
      {"(3/2)", 1.5},       {"(13/4)", 3.25},     {"(-3)", -3.0},       {"(5)", 5.0}};
  std::vector<SymbolicFunction> fs;
  for (const auto& [text, n] : powers) fs.push_back(parse("(x^2 + y^2 + 1/4)^" + text));
  // The same powers inside products, where negative ones become divisions.
  for (const auto& [text, n] : powers) fs.push_back(parse("3*x*(x^2 + y^2 + 1/4)^" + text));
  const FunctionBatch batch(fs);
  const Eigen::Matrix2Xd points = unit_square_points();
  Eigen::MatrixXd values;
  batch.evaluate(points, values);
  const int m = static_cast<int>(powers.size());
  for (int i = 0; i < m; ++i) {
    const double n = powers[i].second;
    // Both bases (sums of positive terms) are within 3 ulp of the exact one, which moves b^n by
    // 3 |n| ulp; std::pow adds one.
    const double tolerance = (5 + 2 * 4 + 3 * 4 + 1) * kEps;
    for (int k = 0; k < points.cols(); ++k) {
      const double x = points(0, k), y = points(1, k);
      const double power = std::pow(x * x + y * y + 0.25, n);
      EXPECT_NEAR(values(i, k), power, tolerance * power) << powers[i].first << " at " << k;
      // Two more roundings: 3 x and the product.
      EXPECT_NEAR(values(m + i, k), 3 * x * power, (tolerance + 2 * kEps) * 3 * x * power)
          << "3 x b^" << powers[i].first << " at " << k;
    }
  }
}

// Transcendental data: the jets and sources of the shipped kinds of exact solutions agree with the
// scalar muParser evaluation to round-off relative to the size of the terms of the derivative of
// that order (π^k for the sines, 1 for exp·cos on [-0.9, 0.9]², c_k r^(2/3 - k) for the corner
// singularity, c_k the sum of the absolute coefficients of its terms, which cancel): each
// evaluation makes a few dozen roundings, within 4 ulp in the vector math.
TEST(ExpressionVectorProgram, TranscendentalJetsAgreeWithMuParser) {
  const double pi = std::numbers::pi;
  struct Case {
    const char* text;
    double scale_per_order;  ///< derivatives of order k are at most scale^k in size
    bool singular;
  };
  const std::vector<Case> cases = {{"sin(pi*x)*sin(pi*y)", pi, false},
                                   {"exp(x)*cos(y)", std::exp(0.9), false},
                                   {"(x^2 + y^2)^(1/3) * sin(2/3 * (atan2(x - y, -x - y) + 3*pi/4))", 1, true}};
  const std::vector<int> order = {0, 1, 1, 2, 2, 2, 4};
  const std::vector<double> singular_terms = {1, 2, 2, 3, 3, 3, 200};  // c_k, from the printed derivatives
  Eigen::Matrix2Xd points = unit_square_points();
  points.array() = points.array() * 1.8 - 0.9;  // around the origin, in all quadrants
  for (const Case& c : cases) {
    const SymbolicFunction u = parse(c.text);
    std::vector<SymbolicFunction> fs = jet(u);
    fs.push_back(u.bilaplacian());
    const FunctionBatch batch(fs);
    Eigen::MatrixXd values;
    batch.evaluate(points, values);
    for (size_t f = 0; f < fs.size(); ++f)
      for (int k = 0; k < points.cols(); ++k) {
        const double r = points.col(k).norm();
        const double scale = c.singular ? singular_terms[f] * std::pow(r, 2.0 / 3 - order[f])
                                        : std::pow(c.scale_per_order, order[f]);
        const double single = fs[f](points.col(k));
        EXPECT_NEAR(values(static_cast<int>(f), k), single, 1e-13 * (1 + scale))
            << c.text << ", function " << f << " at (" << points(0, k) << ", " << points(1, k) << ")";
      }
  }
}

// Results that are inputs, constants, zero or repeated, next to a long program whose work slots are
// reused: each column is what its function gives alone.
TEST(ExpressionVectorProgram, InputsConstantsAndRepeatsAmongReusedSlots) {
  const SymbolicFunction u = parse("x^3*y - 2*x*y^2 + pi*x^2 + 3 + exp(x*y)*sin(x+y)");
  std::vector<SymbolicFunction> fs = jet(u);
  for (const char* text : {"x", "y", "2.5", "pi*x^2*y - x/7", "x^3*y - 2*x*y^2 + pi*x^2 + 3 + exp(x*y)*sin(x+y)"})
    fs.push_back(parse(text));
  fs.push_back(SymbolicFunction());
  fs.push_back(fs[1]);
  const FunctionBatch batch(fs);
  const Eigen::Matrix2Xd points = unit_square_points();
  Eigen::MatrixXd values;
  batch.evaluate(points, values);
  ASSERT_EQ(values.rows(), static_cast<int>(fs.size()));
  for (size_t f = 0; f < fs.size(); ++f)
    for (int k = 0; k < points.cols(); ++k) {
      const double single = fs[f](points.col(k));
      EXPECT_NEAR(values(static_cast<int>(f), k), single, 1e-13 * (1 + std::abs(single)))
          << "function " << f << " at " << k;
    }
  EXPECT_EQ(values.row(6), points.row(0));
  EXPECT_EQ(values.row(7), points.row(1));
  EXPECT_TRUE((values.row(8).array() == 2.5).all());
  EXPECT_TRUE((values.row(fs.size() - 2).array() == 0.0).all());
  // Every count of functions (the results are stored four and two at a time, then one by one):
  // the first m functions alone give the same values, bit for bit (the functions are compiled in
  // order, so a prefix compiles to the same instructions).
  for (size_t m = 1; m <= 7; ++m) {
    const std::vector<SymbolicFunction> first(fs.begin(), fs.begin() + static_cast<std::ptrdiff_t>(m));
    Eigen::MatrixXd some;
    FunctionBatch(first).evaluate(points, some);
    EXPECT_EQ(some, values.topRows(static_cast<Eigen::Index>(m))) << m << " functions";
  }
}

}  // namespace
}  // namespace iga
