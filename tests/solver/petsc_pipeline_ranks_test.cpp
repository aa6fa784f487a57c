// The PETSc path of the one pipeline on one and on two ranks.
//
// Acceptance: a WS4 clamped plate whose exact solution, a quartic
// with inhomogeneous boundary data, lies in the space, solved through PETSc with MUMPS at 35 850
// DOFs on one and on two ranks, is at round-off (relative L2 error ≤ 1e-13) as the serial solve is.
// With the element matrices summed in long double (the PETSc path before the pipeline was one) the
// plate's error grows like ε_ld h⁻⁴ instead (docs/known-limits.md: 9.8e-13 at 9 226 DOFs, ×16 per
// level); the serial path sums in double-double, and so does the PETSc path now.
//
// Laplace–Beltrami without reaction on a closed surface (its load made orthogonal to constants,
// one coefficient pinned, the mean shifted: sums over all ranks) gives the serial solution, and so
// do Kirchhoff–Love shells (three unknowns per function, held rotations, free rigid motions).
//
// The two-rank case starts this test program under mpirun (the cases ...OnTheRanksOfThisRun with a
// rank count in the environment), as a user starts iga-run.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "assembly/error_norms.hpp"
#include "solver/petsc_session.hpp"
#include "solver/petsc_settings.hpp"
#include "solver/rank_part.hpp"
#include "solver/solve_problem.hpp"
#include "tests/support/rerun_under_mpirun.hpp"
#include "tests/support/shell_configs.hpp"
#include "tests/support/test_support.hpp"

namespace iga {
namespace {

constexpr const char* kPlate = R"yaml(
problem: {pde: biharmonic, exact: "x^4 + x^3*y - 2*x^2*y^2 + x*y^3 - y^4 + x^2 - y + 1", boundary: {all: clamped}}
domain: {type: unit_square}
space: {type: ws4, elements: 2}
)yaml";
constexpr int kLevel = 4;  // 35 850 DOFs (docs/spaces/ws4.md)

TEST(PetscWs4Plate, InSpaceQuarticAtRoundOffOnTheRanksOfThisRun) {
  if (!petsc_available()) GTEST_SKIP() << "built without PETSc";
  const ProblemSpec problem = test::problem_from_yaml(kPlate);
  const SpacePtr space = test::space_from_yaml(kPlate, kLevel);
  ASSERT_EQ(space->dimension(), 35850);
  PetscSettings petsc = default_petsc_settings(problem.pde);
  petsc.ksp = "preonly";
  petsc.pc = "mumps";
  const DiscreteSolution p = solve_problem(*space, problem, SolverKind::petsc, {}, petsc);
  ASSERT_EQ(mpi_size(), test::expected_ranks("IGA_PLATE_TEST_RANKS"));
  // ‖u‖_L2: the error of the zero function.
  const double norm = error_norms(*space, Eigen::VectorXd::Zero(space->dimension()), problem.exact_solution(),
                                  space->error_quadrature_degree())
                          .l2;
  std::printf("rank %d of %d: %s, relative errors L2 %.2e, H1 %.2e, H2 %.2e\n", mpi_rank(), mpi_size(),
              p.solve.method.c_str(), *p.result.l2 / norm, *p.result.h1 / norm, *p.result.h2 / norm);
  EXPECT_GE(p.solve.refinement_steps, 1);
  EXPECT_LE(*p.result.l2 / norm, 1e-13);
  if (mpi_size() > 1) return;
  // The serial solve of the same system, for comparison: at round-off too.
  const DiscreteSolution serial = solve_problem(*space, problem, SolverKind::cholmod);
  std::printf("serial: relative L2 error %.2e\n", *serial.result.l2 / norm);
  EXPECT_LE(*serial.result.l2 / norm, 1e-13);
}

TEST(PetscSurface, LaplaceBeltramiGivesTheSerialSolutionOnTheRanksOfThisRun) {
  if (!petsc_available()) GTEST_SKIP() << "built without PETSc";
  // Closed without reaction (load orthogonal to constants, one coefficient pinned, mean shifted:
  // sums over all ranks), and open with Dirichlet data on the boundary curve.
  for (const char* yaml : {R"yaml(
problem: {pde: laplace_beltrami, exact: "x*y + sin(z) + x", reaction: 0}
domain: {type: surface, mesh: icosphere, level: 1}
space: {type: surface, degree: 2}
)yaml",
                           R"yaml(
problem: {pde: laplace_beltrami, exact: "x*y + sin(z) + x", boundary: {all: dirichlet}}
domain: {type: surface, mesh: height_field}
space: {type: surface, degree: 3}
)yaml"}) {
    SCOPED_TRACE(yaml);
    const ProblemSpec problem = test::problem_from_yaml(yaml);
    const SpacePtr space = test::space_from_yaml(yaml, 2);
    PetscSettings petsc = default_petsc_settings(problem.pde);
    petsc.ksp = "preonly";
    petsc.pc = "mumps";
    const DiscreteSolution p = solve_problem(*space, problem, SolverKind::petsc, {}, petsc);
    ASSERT_EQ(mpi_size(), test::expected_ranks("IGA_PLATE_TEST_RANKS"));
    const DiscreteSolution serial = solve_problem(*space, problem, SolverKind::cholmod);
    const double difference = (p.coefficients - serial.coefficients).norm() / serial.coefficients.norm();
    std::printf("rank %d of %d: %d dofs, L2 %.6e (serial %.6e), coefficients differ by %.1e\n", mpi_rank(),
                mpi_size(), space->dimension(), *p.result.l2, *serial.result.l2, difference);
    EXPECT_EQ(p.result.free_dofs, serial.result.free_dofs);
    // Two factorizations of one system conditioned like h⁻²: round-off apart.
    EXPECT_LT(difference, 1e-12);
    EXPECT_NEAR(*p.result.l2, *serial.result.l2, 1e-10 * *serial.result.l2);
    EXPECT_NEAR(*p.result.h1, *serial.result.h1, 1e-10 * *serial.result.h1);
  }
}

// Each rank on its part of the space (rank_part.hpp): only its own elements, the boundary band and
// (for G1 jumps) its neighbours, the functions renumbered. The coefficients each rank gets back are
// the serial solution's at the part's functions, the errors (summed over the ranks) the serial ones,
// and the counts those of the whole problem.
TEST(PetscParts, EachRankSolvesOnItsPartAndGetsTheSerialSolutionOnTheRanksOfThisRun) {
  if (!petsc_available()) GTEST_SKIP() << "built without PETSc";
  for (const char* yaml : {kPlate, R"yaml(
problem: {pde: laplace_beltrami, exact: "x*y + sin(z) + x", boundary: {all: dirichlet}}
domain: {type: surface, mesh: height_field}
space: {type: surface, degree: 3}
)yaml",
                           R"yaml(
problem: {pde: biharmonic, exact: "sin(2*x + 0.3)*cos(3*y)", boundary: {all: clamped}}
domain: {type: multipatch, name: 3p_square}
space: {type: g1, degree: 5}
)yaml",
                           // Dependent boundary traces at the valence-3 corners (a pivoted choice
                           // of which functions to constrain): every rank must choose as the whole
                           // space does, whatever its own elements are.
                           R"yaml(
problem: {pde: poisson, exact: "sin(2*x+0.3)*cos(3*y)", boundary: {all: dirichlet}}
domain: {type: multipatch, name: fan3}
space: {type: g1_4split, degree: 4, blending: linear, refinement: nested}
)yaml"}) {
    SCOPED_TRACE(yaml);
    const ProblemSpec problem = test::problem_from_yaml(yaml);
    const SpacePtr space = test::space_from_yaml(yaml, 2);
    ensure_petsc_initialised();  // the ranks are known from here on
    const std::shared_ptr<const SpacePart> part = rank_part(space, mpi_rank(), mpi_size());
    ASSERT_EQ(mpi_size(), test::expected_ranks("IGA_PLATE_TEST_RANKS"));
    PetscSettings petsc = default_petsc_settings(problem.pde);
    petsc.ksp = "preonly";
    petsc.pc = "mumps";
    const DiscreteSolution p = solve_problem(*part, problem, SolverKind::petsc, {}, petsc);
    const DiscreteSolution serial = solve_problem(*space, problem, SolverKind::cholmod);
    ASSERT_EQ(p.coefficients.size(), part->dimension());
    double difference = 0;
    for (int i = 0; i < part->dimension(); ++i)
      difference = std::max(difference, std::abs(p.coefficients(i) - serial.coefficients(part->global_dofs()[i])));
    difference /= serial.coefficients.cwiseAbs().maxCoeff();
    std::printf("rank %d of %d: part of %d of %d functions (%d of %d elements own), L2 %.6e (serial %.6e), "
                "coefficients differ by %.1e\n",
                mpi_rank(), mpi_size(), part->dimension(), space->dimension(), static_cast<int>(part->owned_elements().size()),
                space->num_elements(), *p.result.l2, *serial.result.l2, difference);
    EXPECT_EQ(p.result.dofs, serial.result.dofs);
    EXPECT_EQ(p.result.elements, serial.result.elements);
    EXPECT_EQ(p.result.free_dofs, serial.result.free_dofs);
    if (mpi_size() > 1) EXPECT_LT(part->dimension(), space->dimension());
    // Two factorizations of one system (conditioned like h⁻⁴ for the plates): round-off apart.
    EXPECT_LT(difference, 1e-10);
    // The plate's exact solution is in the space: errors at round-off there (1e-15), compared absolutely.
    EXPECT_NEAR(*p.result.l2, *serial.result.l2, 1e-10 * *serial.result.l2 + 1e-13);
    EXPECT_NEAR(*p.result.h1, *serial.result.h1, 1e-10 * *serial.result.h1 + 1e-13);
    if (serial.result.g1_jump) EXPECT_LT(*p.result.g1_jump, 1e-8);
  }
}

// Kirchhoff–Love shells (three unknowns per function, in blocks): every rank holds the whole space
// (the pins are a choice over it) and assembles its elements' vector-valued matrices. The quarter
// pinched cylinder has the Nitsche terms of held rotations on its symmetry edges (element matrices
// beyond the integrals) and a point load; the pinched hemisphere is a free shell, all six rigid
// motions pinned and removed after the solve (docs/shells.md).
TEST(PetscShell, GivesTheSerialDisplacementOnTheRanksOfThisRun) {
  if (!petsc_available()) GTEST_SKIP() << "built without PETSc";
  for (const char* yaml : {R"yaml(
problem:
  pde: kirchhoff_love_shell
  material: {youngs_modulus: 3e6, poisson_ratio: 0.3, thickness: 3}
  point_loads: [{point: [300, 0, 300], force: [0, 0, -0.5]}]
  boundary:
    bottom: {fixed: [y, z]}
    top: {fixed: [x], rotation: held}
    left: {fixed: [z], rotation: held}
    right: {fixed: [z], rotation: held}
domain: {type: surface_patch, shape: cylinder, radius: 300, length: 300, half_angle: 90}
space: {type: bspline, degree: 3, elements: [4, 2]}
)yaml",
                           test::kFreePinchedHemisphere}) {
    SCOPED_TRACE(yaml);
    const ProblemSpec problem = test::problem_from_yaml(yaml);
    const SpacePtr space = test::space_from_yaml(yaml, 1);
    const PetscSettings petsc = default_petsc_settings(problem.pde);  // MUMPS for shells
    const DiscreteSolution p = solve_problem(*space, problem, SolverKind::petsc, {}, petsc);
    ASSERT_EQ(mpi_size(), test::expected_ranks("IGA_PLATE_TEST_RANKS"));
    const DiscreteSolution serial = solve_problem(*space, problem, SolverKind::cholmod);
    ASSERT_EQ(p.coefficients.size(), 3 * space->dimension());
    const double difference =
        (p.coefficients - serial.coefficients).cwiseAbs().maxCoeff() / serial.coefficients.cwiseAbs().maxCoeff();
    std::printf("rank %d of %d: %s, %d unknowns (%d free), energy %.12e (serial %.12e), coefficients differ by %.1e\n",
                mpi_rank(), mpi_size(), p.solve.method.c_str(), p.result.dofs, p.result.free_dofs,
                p.result.energy.value_or(0.0), serial.result.energy.value_or(0.0), difference);
    EXPECT_EQ(p.result.dofs, 3 * space->dimension());
    EXPECT_EQ(p.result.free_dofs, serial.result.free_dofs);
    // One system, two factorizations: the serial one of the matrix rounded to double, MUMPS's
    // refined against the element sums in double-double, so they differ by κ(K)·ε (measured
    // 4e-12 here, 6e-11 at level 2: the thin hemisphere's membrane and bending stiffnesses are
    // (R/t)² = 6e4 apart); the levels differ by 1e-1.
    EXPECT_LT(difference, 1e-9);
    ASSERT_TRUE(p.result.energy && serial.result.energy);
    EXPECT_NEAR(*p.result.energy, *serial.result.energy, 1e-9 * *serial.result.energy);
  }
}

TEST(PetscPipeline, TheCasesAboveOnTwoRanks) {
  if (!petsc_available()) GTEST_SKIP() << "built without PETSc";
  if (test::expected_ranks("IGA_PLATE_TEST_RANKS") != 1) GTEST_SKIP() << "this is the run started by mpirun";
  EXPECT_EQ(test::rerun_under_mpirun("IGA_PLATE_TEST_RANKS", 2, "*OnTheRanksOfThisRun"), 0);
}

}  // namespace
}  // namespace iga
