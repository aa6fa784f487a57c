// Essential conditions when the boundary traces of the functions seen by the data are linearly
// dependent: G1 vertex functions where parts with different conditions meet. The boundary
// projection then constrains an independent subset and keeps the rest free after a local change of
// basis (assembly/boundary_conditions.hpp). Before that fallback these cases stopped with
// "boundary projection is singular".
#include <gtest/gtest.h>

#include "assembly/boundary_conditions.hpp"
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
