// Patch tests: a solution inside the space is reproduced to round-off, by both direct solvers,
// for every boundary condition kind.
#include <gtest/gtest.h>

#include "solver/solve_problem.hpp"
#include "tests/support/test_support.hpp"

using namespace iga;

namespace {

struct PatchCase {
  const char* name;
  const char* yaml;
};

const PatchCase kCases[] = {
    {"poisson_dirichlet_p2", R"yaml(
problem: {pde: poisson, exact: "1 + x - 2*y + x^2 - 3*x*y + 0.5*y^2", boundary: {all: dirichlet}}
domain: {type: rectangle, min: [-1, 0.5], max: [2, 1.5]}
space: {type: bspline, degree: 2, regularity: 1, elements: [3, 2]}
)yaml"},
    {"poisson_mixed_p3", R"yaml(
problem: {pde: poisson, exact: "x^3 - 3*x*y^2 + 2*x^2*y + y^3 - x", boundary: {all: dirichlet, left: neumann, top: neumann}}
domain: {type: rectangle, min: [0, 0], max: [1, 2]}
space: {type: bspline, degree: 3, regularity: 1, elements: [3, 4]}
)yaml"},
    {"biharmonic_clamped_p3", R"yaml(
problem: {pde: biharmonic, exact: "x^3*y - 2*x^2*y^2 + y^3 + x*y + 1", boundary: {all: clamped}}
domain: {type: rectangle, min: [0, 0], max: [2, 1]}
space: {type: bspline, degree: 3, regularity: 2, elements: [4, 3]}
)yaml"},
    {"biharmonic_hessian_form_p4", R"yaml(
problem: {pde: biharmonic, form: hessian, exact: "x^4 - x^2*y^2 + 3*x*y^3 - y", boundary: {all: clamped}}
domain: {type: rectangle, min: [0, 0], max: [1, 1]}
space: {type: bspline, degree: 4, regularity: 2, elements: [3, 3]}
)yaml"},
    {"biharmonic_simply_supported_p3", R"yaml(
problem: {pde: biharmonic, exact: "x^3 + x^2*y - y^3 + 2", boundary: {all: simply_supported}}
domain: {type: rectangle, min: [0, 0], max: [1, 1]}
space: {type: bspline, degree: 3, regularity: 2, elements: [3, 3]}
)yaml"},
    {"poisson_trapezoid_patch_p3", R"yaml(
problem: {pde: poisson, exact: "x^2 - x*y + 2*y^2 + x - 1", boundary: {all: dirichlet}}
domain: {type: patch, degree: [1, 1], knots_u: [0, 0, 1, 1], knots_v: [0, 0, 1, 1], control_points: [[0, 0], [2, 0], [0.3, 1], [1.2, 1.4]]}
space: {type: bspline, degree: 3, elements: [4, 4]}
)yaml"},
    // A bilinear (non-affine) map: the physical Hessians need the geometry's second derivatives.
    // Its integrands are rational, so Gauss quadrature is consistent only up to its own error
    // (1e-9 on 2x2 elements): 4x4 elements bring that below the tolerances.
    {"biharmonic_trapezoid_patch_p3", R"yaml(
problem: {pde: biharmonic, exact: "x^2 - x*y + 2*y^2 + x - 1", boundary: {all: clamped}}
domain: {type: patch, degree: [1, 1], knots_u: [0, 0, 1, 1], knots_v: [0, 0, 1, 1], control_points: [[0, 0], [2, 0], [0.3, 1], [1.2, 1.4]]}
space: {type: bspline, degree: 3, elements: [4, 4]}
)yaml"},
    {"biharmonic_mixed_p3", R"yaml(
problem: {pde: biharmonic, exact: "x^2*y^3 - x*y + 4", boundary: {all: clamped, bottom: simply_supported, right: simply_supported}}
domain: {type: rectangle, min: [0, 0], max: [1, 1]}
space: {type: bspline, degree: 3, regularity: 2, elements: [4, 4]}
)yaml"},
};

class PatchTest : public ::testing::TestWithParam<PatchCase> {};

}  // namespace

TEST_P(PatchTest, PolynomialSolutionIsReproduced) {
  const PatchCase& c = GetParam();
  const ProblemSpec problem = test::problem_from_yaml(c.yaml);
  const SpacePtr space = test::space_from_yaml(c.yaml);
  for (SolverKind solver : {SolverKind::cholmod, SolverKind::umfpack}) {
    const DiscreteSolution s = solve_problem(*space, problem, solver);
    ASSERT_TRUE(s.result.l2 && s.result.h1 && s.result.h2);
    EXPECT_LT(*s.result.l2, 1e-10) << c.name;
    EXPECT_LT(*s.result.h1, 1e-9) << c.name;
    EXPECT_LT(*s.result.h2, 1e-8) << c.name;
    EXPECT_GT(s.result.free_dofs, 0);
    EXPECT_EQ(s.solve.method, solver == SolverKind::cholmod ? "cholmod" : "umfpack");  // no silent fallback
    EXPECT_LT(s.solve.relative_residual, 1e-10);
  }
}

INSTANTIATE_TEST_SUITE_P(BSpline, PatchTest, ::testing::ValuesIn(kCases),
                         [](const auto& info) { return std::string(info.param.name); });

// Without `exact`: explicit source and boundary data. No errors are reported, so the solution is
// compared with the known polynomial here.
TEST(ExplicitData, SourceAndBoundaryDataWithoutExactSolution) {
  struct Case {
    const char* yaml;
    const char* solution;
  };
  const Case cases[] = {
      {R"yaml(
problem: {pde: poisson, source: "-4", data: {u: "x^2 + y^2 - x*y"}, boundary: {all: dirichlet}}
domain: {type: rectangle, min: [0, 0], max: [1, 1]}
space: {type: bspline, degree: 2, elements: [3, 3]}
)yaml",
       "x^2 + y^2 - x*y"},
      {R"yaml(
problem: {pde: biharmonic, source: "0", data: {u: "x^3*y + y^2", laplace_u: "6*x*y + 2"}, boundary: {all: simply_supported}}
domain: {type: rectangle, min: [0, 0], max: [1, 1]}
space: {type: bspline, degree: 4, elements: [3, 3]}
)yaml",
       "x^3*y + y^2"},
  };
  for (const Case& c : cases) {
    const ProblemSpec problem = test::problem_from_yaml(c.yaml);
    ASSERT_FALSE(problem.exact.has_value());
    const SpacePtr space = test::space_from_yaml(c.yaml);
    const DiscreteSolution s = solve_problem(*space, problem, SolverKind::cholmod);
    EXPECT_FALSE(s.result.l2.has_value());
    const ProblemSpec reference = manufactured_problem(problem.pde, SymbolicFunction::parse(c.solution, "test"), {});
    const ErrorNorms e = error_norms(*space, s.coefficients, reference.exact_solution(), 12);
    EXPECT_LT(e.l2, 1e-11) << c.solution;
    EXPECT_LT(*e.h2, 1e-9) << c.solution;
  }
}
