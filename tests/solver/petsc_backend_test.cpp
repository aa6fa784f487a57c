// The PETSc path on one rank against CHOLMOD, on shipped configs of every space, planar and on
// surfaces: the same errors to the solver tolerance (nothing in the PETSc path is specific to a
// space or a problem), and its failures.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "config/errors.hpp"
#include "solver/petsc_settings.hpp"
#include "solver/solve_problem.hpp"
#include "spaces/space_factory.hpp"

namespace iga {
namespace {

struct Case {
  const char* config;
  int level;
  const char* ksp;
  const char* pc;
};

/// Relative difference of two error values.
double relative(double a, double b) { return std::abs(a - b) / std::abs(b); }

class PetscAgainstCholmod : public ::testing::TestWithParam<Case> {};

TEST_P(PetscAgainstCholmod, SameErrorsAndCoefficients) {
  if (!petsc_available()) GTEST_SKIP() << "built without PETSc";
  const Case c = GetParam();
  const ConfigNode root = ConfigNode::load_file(std::string(IGA_SOURCE_DIR) + "/configs/" + c.config + ".yaml");
  const ProblemSpec problem = parse_problem(root["problem"]);
  const SpacePtr space = make_space(root["domain"], root["space"], c.level);
  PetscSettings petsc = default_petsc_settings(problem.pde);
  petsc.ksp = c.ksp;
  petsc.pc = c.pc;
  const DiscreteSolution direct = solve_problem(*space, problem, SolverKind::cholmod);
  const DiscreteSolution p = solve_problem(*space, problem, SolverKind::petsc, {}, petsc);
  std::printf("%s level %d (%d dofs): %s, L2 %.6e vs %.6e, relative residual %.1e\n", c.config, c.level,
              space->dimension(), p.solve.method.c_str(), *p.result.l2, *direct.result.l2, p.solve.relative_residual);
  ASSERT_EQ(p.result.free_dofs, direct.result.free_dofs);
  // Both solve the same reduced system: the solutions differ by the KSP's tolerance (rtol 1e-12,
  // times the preconditioned condition number, which AMG keeps small) or, for a direct method,
  // by the factorization's round-off amplified by the condition number (h⁻⁴ at these small levels).
  const double coefficient_difference =
      (p.coefficients - direct.coefficients).norm() / direct.coefficients.norm();
  EXPECT_LT(coefficient_difference, 1e-8);
  EXPECT_LT(relative(*p.result.l2, *direct.result.l2), 1e-8);
  EXPECT_LT(relative(*p.result.h1, *direct.result.h1), 1e-8);
  if (direct.result.h2) EXPECT_LT(relative(*p.result.h2, *direct.result.h2), 1e-8);
  EXPECT_LT(p.solve.relative_residual, 1e-9);
}

INSTANTIATE_TEST_SUITE_P(
    EverySpace, PetscAgainstCholmod,
    ::testing::Values(Case{"bspline-poisson", 2, "cg", "gamg"}, Case{"bspline-poisson", 2, "cg", "hypre"},
                      Case{"bspline-poisson", 2, "gmres", "ilu"}, Case{"bspline-biharmonic", 2, "preonly", "mumps"},
                      Case{"bspline-biharmonic", 2, "preonly", "cholesky"}, Case{"ws4-poisson", 1, "cg", "gamg"},
                      Case{"ws4-biharmonic", 1, "preonly", "mumps"}, Case{"tmesh-poisson-trig", 2, "cg", "gamg"},
                      Case{"tmesh-biharmonic", 2, "preonly", "mumps"}, Case{"g1-poisson-3patch", 1, "cg", "gamg"},
                      Case{"g1-biharmonic-3patch", 1, "preonly", "mumps"},
                      // clamped, simply supported and free parts meeting at vertices
                      Case{"g1-biharmonic-mixed", 1, "preonly", "mumps"},
                      // Laplace–Beltrami on surfaces: the same pipeline with the surface formulation
                      Case{"surface-laplace-beltrami-sphere", 2, "cg", "gamg"},
                      Case{"surface-laplace-beltrami-sphere", 2, "preonly", "mumps"},
                      Case{"g1_4split-surface-cube", 1, "cg", "gamg"}),
    [](const ::testing::TestParamInfo<Case>& info) {
      std::string name = std::string(info.param.config) + "_" + info.param.ksp + "_" + info.param.pc;
      for (char& ch : name)
        if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
      return name;
    });

// A quintic G1 plate fine enough that the double-precision matrix alone would leave an error floor
// (entry errors ε|K| act on the solution like ε h⁻⁴: with MUMPS on the double matrix the L2 error
// came out 1.5 times CHOLMOD's at this level). Refined with residuals of the matrix kept in long
// double, the factorization's solution is the Galerkin solution to round-off, as CHOLMOD's is.
TEST(PetscSolve, RefinementWithTheExtendedMatrixRemovesTheDoublePrecisionFloorOfPlates) {
  if (!petsc_available()) GTEST_SKIP() << "built without PETSc";
  const ConfigNode root = ConfigNode::load_file(std::string(IGA_SOURCE_DIR) + "/configs/g1-biharmonic-3patch.yaml");
  const ProblemSpec problem = parse_problem(root["problem"]);
  const SpacePtr space = make_space(root["domain"], root["space"], 5);
  const DiscreteSolution direct = solve_problem(*space, problem, SolverKind::cholmod);
  const DiscreteSolution p = solve_problem(*space, problem, SolverKind::petsc, {}, default_petsc_settings(problem.pde));
  const double coefficient_difference = (p.coefficients - direct.coefficients).norm() / direct.coefficients.norm();
  std::printf("level 5 (%d dofs): %s, L2 %.6e vs %.6e, coefficients differ by %.1e\n", space->dimension(),
              p.solve.method.c_str(), *p.result.l2, *direct.result.l2, coefficient_difference);
  EXPECT_GE(p.solve.refinement_steps, 1);
  // Round-off of two refined solutions (ε times a modest factor) against an L2 error of 2e-11.
  EXPECT_LT(coefficient_difference, 1e-12);  // without the refinement: 1e-11 and more
  EXPECT_LT(relative(*p.result.l2, *direct.result.l2), 1e-3);
  EXPECT_LT(relative(*p.result.h2, *direct.result.h2), 1e-6);
}

TEST(PetscSolve, UnconvergedKrylovMethodIsANumericalErrorWithTheReason) {
  if (!petsc_available()) GTEST_SKIP() << "built without PETSc";
  const ConfigNode root = ConfigNode::load_file(std::string(IGA_SOURCE_DIR) + "/configs/bspline-poisson.yaml");
  const ProblemSpec problem = parse_problem(root["problem"]);
  const SpacePtr space = make_space(root["domain"], root["space"], 2);
  PetscSettings petsc = default_petsc_settings(problem.pde);
  petsc.pc = "ilu";
  petsc.max_iterations = 3;  // CG with ILU(0) needs tens of iterations for rtol 1e-12 here
  try {
    solve_problem(*space, problem, SolverKind::petsc, {}, petsc);
    FAIL() << "expected a NumericalError";
  } catch (const NumericalError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("DIVERGED_ITS after 3 iterations"), std::string::npos) << what;
    EXPECT_NE(what.find("last residual norms"), std::string::npos) << what;
  }
}

TEST(PetscSolve, OptionsSetInCodeAreHeldToTheAllowListToo) {
  if (!petsc_available()) GTEST_SKIP() << "built without PETSc";
  const ConfigNode root = ConfigNode::load_file(std::string(IGA_SOURCE_DIR) + "/configs/bspline-poisson.yaml");
  const ProblemSpec problem = parse_problem(root["problem"]);
  const SpacePtr space = make_space(root["domain"], root["space"], 1);
  PetscSettings petsc = default_petsc_settings(problem.pde);
  petsc.options = "-ksp_rtol 1e-10 -log_view :/proc/iga-run-test-log.txt";  // bypasses parse_solver_settings
  try {
    solve_problem(*space, problem, SolverKind::petsc, {}, petsc);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("-log_view is not an option a config may set"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace iga
