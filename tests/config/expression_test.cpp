#include "config/expression.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <thread>
#include <vector>

#include "config/errors.hpp"
#include "quadrature/quadrature_rule.hpp"  // Point2

namespace iga {
namespace {

constexpr double kPi = std::numbers::pi;

SymbolicFunction parse(const std::string& text) { return SymbolicFunction::parse(text, "test.yaml:1:1: f"); }

/// Points away from the origin and the axes, in all four quadrants.
const std::vector<Point2>& points() {
  static const std::vector<Point2> pts = {{0.3, 0.7},    {0.11, 0.23}, {-0.6, 0.45},
                                          {-0.35, -0.8}, {0.9, -0.15}, {1.7, 2.3}};
  return pts;
}

/// |a - b| <= tol * max(1, |b|)
void expect_close(double a, double b, double tol, const std::string& what) {
  EXPECT_LE(std::abs(a - b), tol * std::max(1.0, std::abs(b))) << what << ": got " << a << ", expected " << b;
}

TEST(Expression, ValuesOfParsedExpressions) {
  struct Case {
    const char* text;
    double x, y, value;
  };
  const Case cases[] = {
      {"x^2 + 3*y", 2.0, -1.0, 1.0},
      {"1/2*x", 3.0, 0.0, 1.5},
      {"x/y/2", 3.0, 4.0, 0.375},
      {"x^(-1)", 4.0, 0.0, 0.25},
      {"x^(-2)*y", 2.0, 3.0, 0.75},
      {"sqrt(x)", 4.0, 0.0, 2.0},
      {"x^(1/3)", 8.0, 0.0, 2.0},
      {"x^(-3/2)", 4.0, 0.0, 0.125},
      {"pow(x, 3) - y", 2.0, 1.0, 7.0},
      {"x^2.5", 4.0, 0.0, 32.0},
      {"exp(x)", 1.0, 0.0, std::exp(1.0)},
      {"log(x)", std::exp(2.0), 0.0, 2.0},  // natural log (muParser's "log" once meant log10)
      {"abs(x - 3)", 1.0, 0.0, 2.0},
      {"atan2(y, x)", -1.0, 1.0, 0.75 * kPi},
      {"atan(x)", 1.0, 0.0, 0.25 * kPi},
      {"sinh(x) + cosh(y)", 0.5, -0.3, std::sinh(0.5) + std::cosh(-0.3)},
      {"tanh(x)*tan(y)", 0.5, 0.2, std::tanh(0.5) * std::tan(0.2)},
      {"asin(x) + acos(y)", 0.5, 0.2, std::asin(0.5) + std::acos(0.2)},
      {"pi", 0.0, 0.0, kPi},
      {"Pi*x", 2.0, 0.0, 2 * kPi},  // GiNaC's parser knows Pi by itself
      {"sin(pi*x)*cos(pi*y)", 0.25, 1.0 / 3.0, std::sin(kPi / 4) * std::cos(kPi / 3)},
      {"2.5e-3*x - 1e20", 2.0, 0.0, 0.005 - 1e20},
      {"1e-12*x", 3.0, 0.0, 3e-12},
      {"(x+y)^3", 1.0, 2.0, 27.0},
      {"-(x+y)^2", 1.0, 2.0, -9.0},
      {"2^x", 3.0, 0.0, 8.0},
      {"x^y", 2.0, 3.0, 8.0},
      {"2^(3^2)", 0.0, 0.0, 512.0},
      {"(-2)^3 + x", 0.0, 0.0, -8.0},
      {"step(x) + step(-y)", 0.5, 0.5, 1.0},
      {"1/(1 + x^2 + y^2)", 1.0, 2.0, 1.0 / 6.0},
      {"3*x/(2*y^2*(1+x))", 1.0, 2.0, 3.0 / 16.0},
  };
  for (const Case& c : cases) {
    const SymbolicFunction f = parse(c.text);
    expect_close(f(c.x, c.y), c.value, 1e-14, std::string(c.text) + " printed as " + f.str());
    expect_close(f(Point2(c.x, c.y)), c.value, 1e-14, c.text);
  }
}

TEST(Expression, UnaryMinusAndPowers) {
  // muParser must read the printed text as GiNaC meant it: -x^2 is -(x^2), whatever the precedences.
  EXPECT_DOUBLE_EQ(parse("-x^2")(3.0, 0.0), -9.0);
  EXPECT_DOUBLE_EQ(parse("-x^2 + 1")(3.0, 0.0), -8.0);
  EXPECT_DOUBLE_EQ(parse("-x^2*y")(3.0, 2.0), -18.0);
  EXPECT_DOUBLE_EQ(parse("-x^2/y")(3.0, 2.0), -4.5);
  EXPECT_DOUBLE_EQ(parse("-x^2 - y^2")(3.0, 2.0), -13.0);
  EXPECT_DOUBLE_EQ(parse("(-x)^2")(3.0, 0.0), 9.0);
  EXPECT_DOUBLE_EQ(parse("(-x)^3")(3.0, 0.0), -27.0);
  EXPECT_DOUBLE_EQ(parse("y - x^2")(3.0, 2.0), -7.0);
  EXPECT_DOUBLE_EQ(parse("x^-2")(2.0, 0.0), 0.25);
  EXPECT_DOUBLE_EQ(parse("-sqrt(x)")(4.0, 0.0), -2.0);
  EXPECT_DOUBLE_EQ(parse("-x^(1/2)")(4.0, 0.0), -2.0);
  EXPECT_DOUBLE_EQ(parse("-1/x^2")(2.0, 0.0), -0.25);
  EXPECT_DOUBLE_EQ((-parse("x^2 - 3*y"))(3.0, 1.0), -6.0);
  // A term printed after a minus must keep its own sign structure.
  EXPECT_DOUBLE_EQ(parse("x - (y - x)^2")(1.0, 3.0), -3.0);
}

TEST(Expression, Constants) {
  const SymbolicFunction c = SymbolicFunction::constant(3.25);
  EXPECT_DOUBLE_EQ(c(0.1, 0.2), 3.25);
  EXPECT_DOUBLE_EQ(c(-5.0, 7.0), 3.25);
  EXPECT_TRUE(c.diff_x().is_zero());
  EXPECT_TRUE(c.laplacian().is_zero());
  EXPECT_DOUBLE_EQ(c.bilaplacian()(0.3, 0.4), 0.0);
  EXPECT_DOUBLE_EQ(SymbolicFunction::constant(-2.0)(1.0, 1.0), -2.0);
  EXPECT_DOUBLE_EQ(SymbolicFunction::constant(1e-300)(1.0, 1.0), 1e-300);
  EXPECT_DOUBLE_EQ((-SymbolicFunction::constant(0.1))(0.0, 0.0), -0.1);
  EXPECT_TRUE(SymbolicFunction::constant(0.0).is_zero());
  EXPECT_FALSE(c.is_zero());
  EXPECT_THROW(SymbolicFunction::constant(std::nan("")), InputError);
  EXPECT_TRUE(parse("x - x").is_zero());
  EXPECT_FALSE(parse("x").is_zero());
}

TEST(Expression, DerivativesOfSineProduct) {
  const SymbolicFunction u = parse("sin(pi*x)*sin(2*pi*y)");
  const SymbolicFunction ux = u.diff_x(), uy = u.diff_y(), lap = u.laplacian(), bilap = u.bilaplacian();
  for (const Point2& p : points()) {
    const double x = p.x(), y = p.y();
    const double v = std::sin(kPi * x) * std::sin(2 * kPi * y);
    expect_close(u(p), v, 1e-14, "u");
    expect_close(ux(p), kPi * std::cos(kPi * x) * std::sin(2 * kPi * y), 1e-13, "u_x");
    expect_close(uy(p), 2 * kPi * std::sin(kPi * x) * std::cos(2 * kPi * y), 1e-13, "u_y");
    expect_close(lap(p), -5 * kPi * kPi * v, 1e-12, "laplacian");
    expect_close(bilap(p), 25 * std::pow(kPi, 4) * v, 1e-12, "bilaplacian");
  }
  expect_close(u.diff_x().diff_y()(0.3, 0.7), 2 * kPi * kPi * std::cos(0.3 * kPi) * std::cos(1.4 * kPi),
               1e-13, "u_xy");
}

TEST(Expression, BiharmonicCosineSolution) {
  const SymbolicFunction u = parse("(cos(4*pi*x)-1)*(cos(4*pi*y)-1)");
  const SymbolicFunction lap = u.laplacian(), bilap = u.bilaplacian();
  // Expansion collects the terms: the bilaplacian stays three products, not a blown-up sum.
  EXPECT_LT(bilap.str().size(), 200u) << bilap.str();
  const double pi2 = kPi * kPi, pi4 = pi2 * pi2;
  for (const Point2& p : points()) {
    const double cx = std::cos(4 * kPi * p.x()), cy = std::cos(4 * kPi * p.y());
    const double expected = 256 * pi4 * (4 * cx * cy - cx - cy);
    const double scale = 256 * pi4 * (4 + 1 + 1);  // cancellation happens at this scale
    EXPECT_LE(std::abs(bilap(p) - expected), 1e-9 * scale) << "at " << p.transpose();
    if (std::abs(expected) > 0.1 * scale) {
      EXPECT_LE(std::abs(bilap(p) - expected), 1e-9 * std::abs(expected)) << "at " << p.transpose();
    }
    expect_close(lap(p), 16 * pi2 * (cx + cy - 2 * cx * cy), 1e-12, "laplacian");
  }
  const double cx = std::cos(4 * kPi * 0.3), cy = std::cos(4 * kPi * 0.7);
  EXPECT_NEAR(bilap(0.3, 0.7) / (256 * pi4), 4 * cx * cy - cx - cy, 1e-12);
}

TEST(Expression, DerivativesOfExpAndSqrt) {
  const SymbolicFunction e = parse("exp(x*y)");
  const SymbolicFunction s = parse("sqrt(1+x^2+y^2)");
  for (const Point2& p : points()) {
    const double x = p.x(), y = p.y(), g = std::exp(x * y), r2 = x * x + y * y;
    expect_close(e.diff_x()(p), y * g, 1e-14, "exp u_x");
    expect_close(e.diff_y()(p), x * g, 1e-14, "exp u_y");
    expect_close(e.laplacian()(p), r2 * g, 1e-14, "exp laplacian");
    expect_close(e.bilaplacian()(p), g * (4 + r2 * r2 + 8 * x * y), 1e-13, "exp bilaplacian");

    // With w = 1 + r^2: Δ w^a = 4a² w^(a-1) - 4a(a-1) w^(a-2).
    const double w = 1 + r2;
    expect_close(s.diff_x()(p), x / std::sqrt(w), 1e-14, "sqrt u_x");
    expect_close(s.diff_y()(p), y / std::sqrt(w), 1e-14, "sqrt u_y");
    expect_close(s.laplacian()(p), std::pow(w, -0.5) + std::pow(w, -1.5), 1e-14, "sqrt laplacian");
    expect_close(s.bilaplacian()(p), std::pow(w, -1.5) + 6 * std::pow(w, -2.5) - 15 * std::pow(w, -3.5),
                 1e-13, "sqrt bilaplacian");
  }
}

TEST(Expression, DerivativesOfMonomial) {
  const SymbolicFunction u = parse("x^5*y^3");
  for (const Point2& p : points()) {
    const double x = p.x(), y = p.y();
    expect_close(u.diff_x()(p), 5 * std::pow(x, 4) * std::pow(y, 3), 1e-14, "u_x");
    expect_close(u.diff_y()(p), 3 * std::pow(x, 5) * y * y, 1e-14, "u_y");
    expect_close(u.laplacian()(p), 20 * std::pow(x, 3) * std::pow(y, 3) + 6 * std::pow(x, 5) * y, 1e-13,
                 "laplacian");
    expect_close(u.bilaplacian()(p), 120 * x * std::pow(y, 3) + 240 * std::pow(x, 3) * y, 1e-13,
                 "bilaplacian");
  }
  EXPECT_TRUE(parse("x^3*y").bilaplacian().is_zero());
}

TEST(Expression, CornerSingularity) {
  // r^(2/3) sin(2θ/3): harmonic away from the origin, gradient (2/3) r^(-1/3) (-sin(θ/3), cos(θ/3)).
  const SymbolicFunction u = parse("(x^2+y^2)^(1/3)*sin(2*atan2(y,x)/3)");
  const SymbolicFunction t = parse("atan2(y, x)");
  for (const Point2& p : points()) {
    const double r = p.norm(), theta = std::atan2(p.y(), p.x());
    expect_close(u(p), std::cbrt(r * r) * std::sin(2 * theta / 3), 1e-14, "u");
    expect_close(u.diff_x()(p), -2.0 / 3 / std::cbrt(r) * std::sin(theta / 3), 1e-13, "u_x");
    expect_close(u.diff_y()(p), 2.0 / 3 / std::cbrt(r) * std::cos(theta / 3), 1e-13, "u_y");
    EXPECT_LE(std::abs(u.laplacian()(p)), 1e-12 * std::pow(r, -4.0 / 3)) << p.transpose();
    EXPECT_LE(std::abs(u.bilaplacian()(p)), 1e-11 * std::pow(r, -10.0 / 3)) << p.transpose();
    expect_close(t.diff_x()(p), -p.y() / (r * r), 1e-14, "atan2_x");
    expect_close(t.diff_y()(p), p.x() / (r * r), 1e-14, "atan2_y");
  }
  // Non-harmonic singular function: Δ r^(2/3) = (2/3)² r^(-4/3).
  const SymbolicFunction v = parse("(x^2+y^2)^(1/3)");
  expect_close(v.laplacian()(0.3, -0.4), 4.0 / 9 * std::pow(0.5, -4.0 / 3), 1e-13, "Δ r^(2/3)");
}

TEST(Expression, AbsAndLogDerivatives) {
  expect_close(parse("abs(x)*y").diff_x()(-2.0, 3.0), -3.0, 1e-15, "d abs");
  expect_close(parse("log(x^2+y^2)").laplacian()(0.3, 0.4), 0.0, 1e-12, "log r² harmonic");
  expect_close(parse("log(x)").bilaplacian()(2.0, 0.0), -6.0 / 16, 1e-15, "d4 log");
}

TEST(Expression, LongExpressionsExceedMuParserLimit) {
  // muParser refuses strings over 20000 characters; this bilaplacian prints far longer and must be
  // split into stages. Compare with the sum of the terms' own bilaplacians.
  std::string text;
  std::vector<SymbolicFunction> terms;
  for (int k = 1; k <= 60; ++k) {
    const std::string term = "sin(" + std::to_string(k) + "*x + y^2/" + std::to_string(k + 1) + ")*exp(x*y/" +
                             std::to_string(k) + ")";
    text += (k > 1 ? " + " : "") + term;
    terms.push_back(parse(term).bilaplacian());
  }
  const SymbolicFunction u = parse(text);
  const SymbolicFunction bilap = u.bilaplacian();
  EXPECT_GT(bilap.str().size(), 20000u);
  for (const Point2& p : points()) {
    double expected = 0, scale = 0;
    for (const SymbolicFunction& t : terms) expected += t(p), scale += std::abs(t(p));
    EXPECT_LE(std::abs(bilap(p) - expected), 1e-12 * scale) << p.transpose();
  }
}

TEST(Expression, ErrorsNameThePlace) {
  auto message = [](const std::string& text) -> std::string {
    try {
      SymbolicFunction::parse(text, "run.yaml:4:10: problem.source");
    } catch (const InputError& e) {
      return e.what();
    }
    return "no error";
  };
  EXPECT_EQ(message("z + 1"),
            "run.yaml:4:10: problem.source: cannot parse 'z + 1': unknown symbol 'z' (known: x, y, pi)");
  EXPECT_EQ(message("pie*x"),
            "run.yaml:4:10: problem.source: cannot parse 'pie*x': unknown symbol 'pie' (known: x, y, pi; did "
            "you mean 'pi'?)");
  EXPECT_EQ(
      message("sin(x"),
      "run.yaml:4:10: problem.source: cannot parse 'sin(x': expected ')' or ',' in argument list, got: EOF");
  EXPECT_EQ(message("2^3^2"),
            "run.yaml:4:10: problem.source: cannot parse '2^3^2': GiNaC cannot chain '^'; add parentheses, "
            "e.g. a^(b^c)");
  for (const char* bad :
       {"x**2", "", "2x", "sinn(x)", "sin(x, y)", "x +", "log(-1)*x", "I*x", "zeta(x)", "x == 1"}) {
    const std::string m = message(bad);
    EXPECT_EQ(m.rfind("run.yaml:4:10: problem.source: cannot parse '" + std::string(bad) + "': ", 0), 0u)
        << m;
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
  }
  EXPECT_THROW(SymbolicFunction::parse("z", ""), InputError);
  // A derivative that muParser cannot evaluate is refused when it is taken, not evaluated as NaN.
  const SymbolicFunction g = parse("tgamma(x)");
  EXPECT_DOUBLE_EQ(g(5.0, 0.0), 24.0);
  EXPECT_THROW(g.diff_x(), InputError);
}

TEST(Expression, FunctionsCalledWithoutArgumentsAreRefused) {
  // GiNaC would look such a call up as "any number of arguments" and evaluate it on nothing.
  for (const char* bad : {"cos()", "x + sin( )", "exp(#comment\n)", "2*sqrt()", "1e2*tan()", "foo()"}) {
    try {
      SymbolicFunction::parse(bad, "run.yaml:4:10: problem.exact");
      ADD_FAILURE() << bad << " was accepted";
    } catch (const InputError& e) {
      const std::string m = e.what();
      EXPECT_EQ(m.rfind("run.yaml:4:10: problem.exact: cannot parse '", 0), 0u) << m;
      EXPECT_NE(m.find("called with no arguments"), std::string::npos) << m;
    }
  }
  EXPECT_DOUBLE_EQ(parse("cos(0) + cos (x) + 2e-1*x")(0.0, 0.0), 2.0);
}

TEST(Expression, PrintedOrderDoesNotDependOnGiNaCsHashes) {
  // GiNaC orders the operands of sums and products by hashes seeded with addresses, so under
  // address randomisation its order changes from run to run (and muParser's rounding with it).
  // The printed form sorts operands by their own text: the same in every run.
  EXPECT_EQ(parse("exp(0.5*x)*sin(2*y+0.3)").bilaplacian().str(), "14.0625*exp(0.5*x)*sin(0.3 + 2*y)");
  EXPECT_EQ(parse("y*cos(x) + x*sin(y) - exp(x*y)").str(), "cos(x)*y + sin(y)*x - exp(x*y)");
}

TEST(Expression, LongUnknownSymbolIsNamedExactly) {
  // The name is longer than any short-string buffer, so a dangling match would read freed heap
  // (the sanitizer build reports it; here the text must still come out whole).
  const std::string name = "averyveryveryverylongsymbolname";
  try {
    SymbolicFunction::parse(name + " + x", "where");
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "where: cannot parse '" + name + " + x': unknown symbol '" + name + "' (known: x, y, pi)");
  }
}

TEST(Expression, ConcurrentEvaluation) {
  const SymbolicFunction f = parse("(cos(4*pi*x)-1)*(cos(4*pi*y)-1)").bilaplacian();
  const SymbolicFunction g = parse("sqrt(1+x^2+y^2)").bilaplacian();
  constexpr int n = 20000;
  auto point = [](int i) { return Point2(std::sin(0.37 * i), std::cos(0.11 * i)); };
  std::vector<double> serial(2 * n);
  for (int i = 0; i < n; ++i) serial[2 * i] = f(point(i)), serial[2 * i + 1] = g(point(i));

  // Two std::threads, each evaluating both functions (and compiling its own muParser copies).
  std::vector<double> a(2 * n), b(2 * n);
  auto work = [&](std::vector<double>& out) {
    for (int i = 0; i < n; ++i) out[2 * i] = f(point(i)), out[2 * i + 1] = g(point(i));
  };
  std::thread t1(work, std::ref(a)), t2(work, std::ref(b));
  t1.join();
  t2.join();
  EXPECT_EQ(a, serial);
  EXPECT_EQ(b, serial);

  // OpenMP threads, interleaved points.
  std::vector<double> c(2 * n);
#pragma omp parallel for num_threads(2) schedule(static, 7)
  for (int i = 0; i < n; ++i) c[2 * i] = f(point(i)), c[2 * i + 1] = g(point(i));
  EXPECT_EQ(c, serial);

  // Parsing and differentiating concurrently is safe too (GiNaC itself is not thread-safe).
  std::vector<double> d(2);
  std::thread p1([&] { d[0] = parse("x^3*y").laplacian()(1.0, 2.0); });
  std::thread p2([&] { d[1] = parse("x*y^3").laplacian()(2.0, 1.0); });
  p1.join();
  p2.join();
  EXPECT_DOUBLE_EQ(d[0], 12.0);
  EXPECT_DOUBLE_EQ(d[1], 12.0);
}

// A batch of u and its derivatives gives what each function gives alone, at every point and from
// several threads (one program computes their shared sines once).
TEST(Expression, BatchMatchesSingleFunctions) {
  const SymbolicFunction u = parse(
      "(cos(4*pi*x)-1)*(cos(4*pi*y)-1) + sqrt(x^2+y^2+1) + atan2(y, x+2)"
      " + exp(-x)*log(2+y) + (x^2+1)^(-3) + (y+2)^(1/3) + 1/sqrt(3+x) + tanh(x*y)");
  const SymbolicFunction ux = u.diff_x(), uy = u.diff_y();
  const SymbolicFunction kinks = parse("abs(x-0.2)*step(y-0.5) + csgn(x-0.3) + asinh(y)");
  const std::vector<SymbolicFunction> fs = {u, ux, uy, ux.diff_x(), ux.diff_y(), uy.diff_y(), SymbolicFunction(), kinks};
  const FunctionBatch batch(fs);
  const int m = static_cast<int>(fs.size());
  ASSERT_EQ(batch.size(), m);
  const int q = 150;  // more than one block of points
  Eigen::Matrix2Xd points(2, q);
  for (int k = 0; k < q; ++k) points.col(k) << 0.37 * k / q - 0.1, 1.3 - 0.9 * k / q;
  std::vector<Eigen::MatrixXd> values(2);
#pragma omp parallel for num_threads(2)
  for (int t = 0; t < 2; ++t) batch.evaluate(points, values[t]);
  for (const Eigen::MatrixXd& v : values) {
    ASSERT_EQ(v.rows(), m);
    ASSERT_EQ(v.cols(), q);
    for (int i = 0; i < m; ++i)
      for (int k = 0; k < q; ++k) {
        const double single = fs[i](points.col(k));
        EXPECT_NEAR(v(i, k), single, 1e-13 * (1 + std::abs(single))) << "function " << i << ", point " << k;
      }
  }
}

// Every function the batch evaluates through the vector math library agrees with the scalar one to
// a few ulp, in full blocks and in a remainder of 3 points (not a multiple of the 2 or 4 lanes), and
// a logarithm of a negative number stays NaN (bad data must still be caught).
TEST(Expression, BatchVectorFunctionsMatchScalarOnes) {
  const std::vector<std::string> texts = {
      "sin(3*x)", "cos(3*y)", "tan(x/2)", "asin(x/2)", "acos(y/2)", "atan(3*x)", "sinh(x)", "cosh(y)",
      "tanh(2*x)", "asinh(3*y)", "acosh(2+y)", "atanh(x/2)", "exp(x+y)", "log(2+x)", "(2+x)^(y/3)",
      "atan2(y, x)"};
  std::vector<SymbolicFunction> fs;
  for (const std::string& t : texts) fs.push_back(parse(t));
  fs.push_back(parse("log(x-5)"));
  const FunctionBatch batch(fs);
  const int q = 128 + 3;  // one full block of VectorProgram::kBlock = 128 points, then a remainder of 3
  Eigen::Matrix2Xd points(2, q);
  for (int k = 0; k < q; ++k) points.col(k) << 1.8 * k / q - 0.9, 0.95 - 1.7 * k / q;
  Eigen::MatrixXd v;
  batch.evaluate(points, v);
  for (size_t i = 0; i < texts.size(); ++i)
    for (int k = 0; k < q; ++k) {
      const double single = fs[i](points.col(k));
      EXPECT_NEAR(v(static_cast<int>(i), k), single, 1e-14 * (1 + std::abs(single))) << texts[i] << " at point " << k;
    }
  for (int k = 0; k < q; ++k) EXPECT_TRUE(std::isnan(v(static_cast<int>(texts.size()), k))) << k;
}

}  // namespace
}  // namespace iga
