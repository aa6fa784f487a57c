// The solver: section: defaults per PDE, PETSc keys only with type petsc, refused combinations.

#include <gtest/gtest.h>

#include "solver/petsc_settings.hpp"
#include "tests/support/input_error.hpp"

namespace iga {
namespace {

struct Parsed {
  SolverKind kind = SolverKind::cholmod;
  PetscSettings petsc;
};

Parsed parse(const std::string& yaml, Pde pde = Pde::poisson) {
  Parsed p;
  parse_solver_settings(ConfigNode::load_string(yaml, "s.yaml")["solver"], pde, p.kind, p.petsc);
  return p;
}

TEST(SolverSettings, DirectSolversTakeNoPetscKeys) {
  EXPECT_EQ(parse("solver: {type: umfpack}").kind, SolverKind::umfpack);
  EXPECT_EQ(parse("solver: {}").kind, SolverKind::cholmod);
  const std::string msg = test::input_error([] { parse("solver: {type: cholmod, ksp: cg}"); });
  EXPECT_NE(msg.find("s.yaml:1:"), std::string::npos) << msg;
  EXPECT_NE(msg.find("solver.ksp"), std::string::npos) << msg;
  EXPECT_NE(msg.find("only used with solver.type: petsc"), std::string::npos) << msg;
}

TEST(SolverSettings, UnknownKeyIsNamedWithASuggestion) {
  const std::string msg = test::input_error([] { parse("solver: {type: petsc, kps: cg}"); });
  EXPECT_NE(msg.find("unknown key 'kps'"), std::string::npos) << msg;
  EXPECT_NE(msg.find("'ksp'"), std::string::npos) << msg;
}

TEST(SolverSettings, DefaultsAreAmgForPoissonAndMumpsForTheBiharmonicProblem) {
  if (!petsc_available()) GTEST_SKIP() << "built without PETSc";
  const Parsed poisson = parse("solver: {type: petsc}");
  EXPECT_EQ(poisson.kind, SolverKind::petsc);
  EXPECT_EQ(poisson.petsc.ksp, "cg");
  EXPECT_EQ(poisson.petsc.pc, "gamg");
  EXPECT_EQ(poisson.petsc.rtol, 1e-12);
  const Parsed plate = parse("solver: {type: petsc}", Pde::biharmonic);
  EXPECT_EQ(plate.petsc.ksp, "preonly");
  EXPECT_EQ(plate.petsc.pc, "mumps");
  const Parsed chosen =
      parse("solver: {type: petsc, ksp: gmres, pc: hypre, rtol: 1e-9, max_iterations: 50, options: \"-ksp_monitor -pc_hypre_boomeramg_strong_threshold 0.5\"}");
  EXPECT_EQ(chosen.petsc.ksp, "gmres");
  EXPECT_EQ(chosen.petsc.pc, "hypre");
  EXPECT_EQ(chosen.petsc.rtol, 1e-9);
  EXPECT_EQ(chosen.petsc.max_iterations, 50);
}

TEST(SolverSettings, ImpossibleCombinationsAndValuesAreRefusedAtTheirKey) {
  if (!petsc_available()) GTEST_SKIP() << "built without PETSc";
  std::string msg = test::input_error([] { parse("solver: {type: petsc, ksp: preonly, pc: gamg}"); });
  EXPECT_NE(msg.find("solver.ksp"), std::string::npos) << msg;
  EXPECT_NE(msg.find("direct"), std::string::npos) << msg;
  msg = test::input_error([] { parse("solver: {type: petsc, pc: amg}"); });
  EXPECT_NE(msg.find("solver.pc"), std::string::npos) << msg;
  msg = test::input_error([] { parse("solver: {type: petsc, rtol: 0}"); });
  EXPECT_NE(msg.find("solver.rtol"), std::string::npos) << msg;
  msg = test::input_error([] { parse("solver: {type: petsc, max_iterations: 0}"); });
  EXPECT_NE(msg.find("solver.max_iterations"), std::string::npos) << msg;
  msg = test::input_error([] { parse("solver: {type: petsc, options: \"-ksp_monitor 1 2\"}"); });
  EXPECT_NE(msg.find("'2' is not a PETSc option name"), std::string::npos) << msg;
  msg = test::input_error([] { parse("solver: {type: petsc}", Pde::laplace_beltrami); });
  EXPECT_NE(msg.find("laplace_beltrami"), std::string::npos) << msg;
}

TEST(SolverSettings, PetscIsRefusedAsInputWhenNotBuiltIn) {
  if (petsc_available()) GTEST_SKIP() << "built with PETSc";
  const std::string msg = test::input_error([] { parse("solver: {type: petsc}"); });
  EXPECT_NE(msg.find("without PETSc"), std::string::npos) << msg;
}

}  // namespace
}  // namespace iga
