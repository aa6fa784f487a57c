// Essential conditions when the boundary traces of the functions seen by the data are linearly
// dependent: G1 vertex functions where parts with different conditions meet. The boundary
// projection then constrains an independent subset and keeps the rest free after a local change of
// basis (assembly/boundary_conditions.hpp). Before that fallback these cases stopped with
// "boundary projection is singular".
#include <gtest/gtest.h>

#include <map>

#include "assembly/boundary_conditions.hpp"
#include "assembly/boundary_projection.hpp"
#include "tests/support/test_support.hpp"

using namespace iga;

namespace {

const char* kMesh = "domain: {type: multipatch, name: 3p_square}\nspace: {type: g1, degree: 5}\n";

std::string config(const std::string& problem) { return "problem: " + problem + "\n" + kMesh; }

}  // namespace

TEST(DependentBoundaryTraces, MixedConditionsTriggerTheBasisChange) {
  const std::string yaml = config(R"yaml({pde: poisson, exact: "x*y", boundary: {all: dirichlet, right: neumann, top: neumann}})yaml");
  const SpacePtr space = test::space_from_yaml(yaml);
  EssentialBoundary essential;
  for (const std::string side : {"left", "bottom"})
    for (const BoundaryEdge& e : space->boundary_edges(side)) essential.value_edges.push_back(e);
  const auto zero = [](const Point2&, const Point2&) { return 0.0; };
  const Constraints c = impose_essential(*space, essential, zero, zero, 12);
  EXPECT_FALSE(c.basis_change.empty());  // the case this test is about
  EXPECT_EQ(static_cast<int>(c.constrained.size() + c.free.size()), space->dimension());
}

TEST(DependentBoundaryTraces, PolynomialSolutionsAreReproduced) {
  for (const std::string problem : {
           std::string(R"yaml({pde: poisson, exact: "x^5 - 2*x^2*y^3 + y^4 + x*y - 1", boundary: {all: dirichlet, right: neumann, top: neumann}})yaml"),
           std::string(R"yaml({pde: biharmonic, exact: "x^4*y - x^2*y^2 + 3*y^3 + x", boundary: {all: clamped, right: simply_supported, top: simply_supported}})yaml")}) {
    const std::string yaml = config(problem);
    const DiscreteSolution s = solve_problem(*test::space_from_yaml(yaml), test::problem_from_yaml(yaml), SolverKind::cholmod);
    EXPECT_LT(*s.result.l2, 1e-9) << problem;
    EXPECT_LT(*s.result.h2, 1e-6) << problem;
  }
}

TEST(DependentBoundaryTraces, MixedConditionsConvergeAtOptimalRates) {
  const test::Rates r = test::last_rates(
      config(R"yaml({pde: poisson, exact: "sin(pi*x)*sin(2*pi*y) + x*y", boundary: {all: dirichlet, right: neumann, top: neumann}})yaml"), 4);
  EXPECT_GT(r.l2, 6 - 0.3);
  EXPECT_GT(r.h1, 5 - 0.3);
  EXPECT_GT(r.h2, 4 - 0.3);
}

// Many dependent traces (the 4-split space on a fine mesh: 6 395 boundary functions at 1.3·10⁶
// DOFs, which the former dense QR refused above 6 000). Synthetic traces on a boundary of
// quadrature points: function i is a hat on points [i, i+2] (independent), and every fifth
// function's trace is the sum of its two neighbours' (dependent, as at a G1 corner). The Gram
// matrix and the right-hand side of g = 1 go in as the unsummed entries impose_essential collects.
TEST(DependentBoundaryTraces, ManyDependentTracesAreSplitWithoutADenseFactorization) {
  constexpr int m = 8000;
  const auto is_dependent = [](int i) { return i % 5 == 2; };
  // Traces as columns of B (points × functions).
  std::vector<std::vector<std::pair<int, double>>> trace(m);
  for (int i = 0; i < m; ++i)
    if (!is_dependent(i))
      trace[i] = {{i, 1.0}, {i + 1, 2.0}, {i + 2, 1.0}};
  for (int i = 0; i < m; ++i)
    if (is_dependent(i)) {
      std::map<int, double> sum;
      for (int j : {i - 1, i + 1})
        for (auto [p, v] : trace[j]) sum[p] += v;
      trace[i].assign(sum.begin(), sum.end());
    }
  std::vector<Eigen::Triplet<double>> gram;
  std::vector<std::pair<int, double>> rhs;
  for (int i = 0; i < m; ++i) {
    std::map<int, double> bi(trace[i].begin(), trace[i].end());
    for (auto [p, v] : trace[i]) rhs.emplace_back(i, v);  // ∫ g tr φ_i with g = 1
    for (int j = std::max(0, i - 4); j < std::min(m, i + 5); ++j) {
      double dot = 0;
      for (auto [p, v] : trace[j])
        if (auto it = bi.find(p); it != bi.end()) dot += it->second * v;
      if (dot != 0) gram.emplace_back(i, j, dot);
    }
  }
  std::vector<int> order(m), local_of(m + 10, -1);
  for (int i = 0; i < m; ++i) order[i] = local_of[i] = i;
  const Constraints c = solve_boundary_projection(m + 10, gram, rhs, order, local_of);
  // Each dependent function is the sum of two independent ones: exactly m/5 are left free with a
  // basis change, the others constrained; the 10 functions the data does not see are free.
  EXPECT_EQ(static_cast<int>(c.constrained.size()), m - m / 5);
  EXPECT_EQ(static_cast<int>(c.free.size()), m / 5 + 10);
  // The free basis function of each dependent φ_k is φ_k minus its trace combination: its trace is
  // zero. Checked on the trace vectors, to round-off.
  std::map<int, std::map<int, double>> change;  // free column → (function → coefficient)
  for (const auto& t : c.basis_change) change[t.col()][t.row()] += t.value();
  int checked = 0;
  for (int column = 0; column < static_cast<int>(c.free.size()); ++column) {
    const int k = c.free[column];
    if (k >= m) continue;
    std::map<int, double> tr;
    for (auto [p, v] : trace[k]) tr[p] += v;
    for (auto [f, a] : change[column])
      for (auto [p, v] : trace[f]) tr[p] += a * v;
    double worst = 0;
    for (auto [p, v] : tr) worst = std::max(worst, std::abs(v));
    EXPECT_LT(worst, 1e-12) << "function " << k;
    ++checked;
  }
  EXPECT_EQ(checked, m / 5);
  // The constrained values are the projection of g = 1 onto the span of the traces: the residual
  // of the lifted trace is orthogonal to every trace, dependent ones included.
  std::map<int, double> lifted;
  for (int f : c.constrained)
    for (auto [p, v] : trace[f]) lifted[p] += c.values(f) * v;
  double worst = 0;
  for (int i = 0; i < m; ++i) {
    double r = 0;
    for (auto [p, v] : trace[i]) r += v * (lifted[p] - 1.0);
    worst = std::max(worst, std::abs(r));
  }
  EXPECT_LT(worst, 1e-10);
}

// Which of two dependent traces is kept: the larger. Pairs of functions with the same trace shape,
// one of them 1000 times smaller (both above the rank threshold), the small one first in half the
// pairs and second in the others, so that an order blind to the sizes (COLAMD's ties) keeps some
// small ones and expresses the large one through them: a coefficient of 1000 in the basis change,
// an ill-conditioned free basis. Keeping the larger gives 1/1000.
TEST(DependentBoundaryTraces, TheLargerOfTwoDependentTracesIsKept) {
  constexpr int pairs = 400, m = 2 * pairs;
  std::vector<Eigen::Triplet<double>> gram;
  std::vector<std::pair<int, double>> rhs;
  for (int p = 0; p < pairs; ++p) {
    const double small = 1e-3;
    const double scale[2] = {p % 2 ? 1.0 : small, p % 2 ? small : 1.0};
    for (int a = 0; a < 2; ++a) {
      rhs.emplace_back(2 * p + a, 4.0 * scale[a]);  // ∫ 1 · hat [1, 2, 1]
      for (int b = 0; b < 2; ++b) gram.emplace_back(2 * p + a, 2 * p + b, 6.0 * scale[a] * scale[b]);
    }
  }
  std::vector<int> order(m), local_of(m);
  for (int i = 0; i < m; ++i) order[i] = local_of[i] = i;
  const Constraints c = solve_boundary_projection(m, gram, rhs, order, local_of);
  ASSERT_EQ(static_cast<int>(c.free.size()), pairs);
  ASSERT_EQ(static_cast<int>(c.basis_change.size()), pairs);
  for (int k : c.free) {
    const int p = k / 2;
    EXPECT_EQ(k % 2, p % 2 ? 1 : 0) << "pair " << p << ": the small trace is the one left free";
  }
  for (const auto& t : c.basis_change) EXPECT_NEAR(std::abs(t.value()), 1e-3, 1e-12);
}
