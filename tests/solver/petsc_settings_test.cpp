// The solver: section: defaults per PDE, PETSc keys only with type petsc, refused combinations;
// and the allow-list of PETSc options a config may set (solver.options), with typed values.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "solver/petsc_option_policy.hpp"
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
  // A billion iterations is a hang, not a solve.
  msg = test::input_error([] { parse("solver: {type: petsc, max_iterations: 1000000000}"); });
  EXPECT_NE(msg.find("solver.max_iterations: max_iterations must be between 1 and 100000"), std::string::npos) << msg;
  msg = test::input_error([] { parse("solver: {type: petsc, options: \"-ksp_max_it 1 2\"}"); });
  EXPECT_NE(msg.find("'2' is not a PETSc option name"), std::string::npos) << msg;
}

TEST(SolverSettings, SurfaceProblemsTakePetscWithTheSecondOrderDefaults) {
  if (!petsc_available()) GTEST_SKIP() << "built without PETSc";
  const Parsed p = parse("solver: {type: petsc}", Pde::laplace_beltrami);
  EXPECT_EQ(p.kind, SolverKind::petsc);
  EXPECT_EQ(p.petsc.ksp, "cg");
  EXPECT_EQ(p.petsc.pc, "gamg");
}

TEST(SolverSettings, PetscIsRefusedAsInputWhenNotBuiltIn) {
  if (petsc_available()) GTEST_SKIP() << "built with PETSc";
  const std::string msg = test::input_error([] { parse("solver: {type: petsc}"); });
  EXPECT_NE(msg.find("without PETSc"), std::string::npos) << msg;
}

/// The message of the InputError parse_config_petsc_options throws for `options`.
std::string refusal(const std::string& options) {
  return test::input_error([&] { parse_config_petsc_options(options); });
}

TEST(ConfigPetscOptions, SolverTuningOptionsPassWithTheirValues) {
  const std::vector<PetscOption> o = parse_config_petsc_options(
      "-ksp_type gmres -ksp_rtol 1e-8 -ksp_atol 0 -ksp_max_it 200 -ksp_gmres_restart 50 -pc_type gamg\n"
      "\t-pc_gamg_threshold 0.02,0.01 -pc_gamg_agg_nsmooths 1 -pc_gamg_repartition true -pc_gamg_coarse_eq_limit 100 "
      "-pc_hypre_boomeramg_strong_threshold 0.5 -pc_hypre_boomeramg_coarsen_type hmis -mat_mumps_icntl_14 50 "
      "-mat_mumps_cntl_1 0.01 -ksp_monitor -ksp_converged_reason -ksp_view :stdout -ksp_monitor_true_residual "
      "ascii:stdout -ksp_initial_guess_nonzero -sub_pc_type ilu -sub_pc_factor_levels 1 -mg_levels_ksp_type "
      "chebyshev -mg_levels_ksp_max_it 2 -mg_coarse_pc_type jacobi -KSP_Norm_Type unpreconditioned -ksp_richardson_scale -0.5");
  ASSERT_EQ(o.size(), 26u);
  EXPECT_EQ(o[0].name, "-ksp_type");
  EXPECT_EQ(o[0].value, "gmres");
  EXPECT_EQ(o[6].value, "0.02,0.01");
  EXPECT_EQ(o[14].name, "-ksp_monitor");
  EXPECT_FALSE(o[14].value.has_value());
  EXPECT_EQ(o[16].value, ":stdout");
  EXPECT_EQ(o[25].value, "-0.5");  // a negative number is a value, not a name
  EXPECT_TRUE(parse_config_petsc_options("").empty());
  EXPECT_TRUE(parse_config_petsc_options("  \n ").empty());
}

TEST(ConfigPetscOptions, OptionsThatTouchFilesDebuggersOrSignalsAreRefusedByName) {
  for (const char* option :
       {"-log_view", "-log_view :/tmp/log.txt", "-log_all", "-log_trace /tmp/t", "-malloc_dump /tmp/x",
        "-malloc_debug", "-malloc_view", "-options_file /etc/passwd", "-options_file_yaml f.yaml",
        "-prefix_push ksp_", "-history /tmp/h", "-on_error_attach_debugger", "-start_in_debugger",
        "-debugger_ranks 0", "-debugger_pause 10", "-no_signal_handler", "-on_error_abort", "-info",
        "-viewer_binary_filename /tmp/b", "-mat_view binary:/tmp/m", "-vec_view", "-ksp_view_mat",
        "-ksp_view_rhs", "-pc_mg_dump_binary", "-ksp_monitor_python f.py", "-ksp_monitor_lg_range",
        "-draw_pause 5", "-saws_port 8080", "-help", "-version", "-options_left", "-LOG_VIEW",
        "-mat_mumps_icntl_1 10", "-mat_mumps_icntl_3 7", "-mat_mumps_icntl_22 1", "-mat_mumps_icntl_014 5",
        "-mat_mumps_cntl_6 1", "-sub_pc_gamg_type agg", "-ksp_type=cg", "-pc_type_forced gamg"}) {
    const std::string msg = refusal(option);
    const std::string name = std::string(option).substr(0, std::string(option).find(' '));
    EXPECT_NE(msg.find(name + " is not an option a config may set"), std::string::npos) << option << ": " << msg;
    EXPECT_NE(msg.find("command line or in PETSC_OPTIONS"), std::string::npos) << msg;
  }
  // A refused option after allowed ones is still found.
  EXPECT_NE(refusal("-ksp_monitor -ksp_rtol 1e-6 -log_view").find("-log_view is not"), std::string::npos);
  // A near miss of an allowed name is suggested.
  EXPECT_NE(refusal("-ksp_montor").find("did you mean -ksp_monitor?"), std::string::npos) << refusal("-ksp_montor");
}

TEST(ConfigPetscOptions, MonitorsAndViewsPrintToStandardOutputOnly) {
  for (const char* option : {"-ksp_monitor mon.txt", "-ksp_monitor /tmp/mon.txt", "-ksp_view ascii:v.txt",
                             "-ksp_view :v.txt", "-ksp_converged_reason ascii:stdout:ascii_info_detail",
                             "-ksp_view binary", "-ksp_view binary:m", "-ksp_view draw", "-ksp_view socket",
                             "-ksp_view saws", "-ksp_monitor stdout", "-ksp_monitor :stderr", "-sub_ksp_view x"}) {
    const std::string msg = refusal(option);
    const std::string name = std::string(option).substr(0, std::string(option).find(' '));
    EXPECT_NE(msg.find(name + " prints to standard output only"), std::string::npos) << option << ": " << msg;
  }
}

TEST(ConfigPetscOptions, ValuesAreCheckedAgainstTheOptionsType) {
  const auto expect = [](const std::string& options, const std::string& text) {
    const std::string msg = refusal(options);
    EXPECT_NE(msg.find(text), std::string::npos) << options << ": " << msg;
  };
  expect("-ksp_max_it abc", "-ksp_max_it takes an integer in [0, 100000], not 'abc'");
  expect("-ksp_max_it 1000000", "-ksp_max_it takes an integer in [0, 100000], not '1000000'");
  expect("-ksp_max_it 1.5", "-ksp_max_it takes an integer");
  expect("-ksp_max_it", "-ksp_max_it needs a value: an integer");
  expect("-ksp_max_it -ksp_monitor", "-ksp_max_it needs a value");
  expect("-ksp_max_it 99999999999999999999", "-ksp_max_it takes an integer");
  expect("-ksp_rtol xyz", "-ksp_rtol takes a finite number in [0, 1], not 'xyz'");
  expect("-ksp_rtol nan", "-ksp_rtol takes a finite number");
  expect("-ksp_rtol inf", "-ksp_rtol takes a finite number");
  expect("-ksp_rtol 2", "-ksp_rtol takes a finite number in [0, 1]");
  expect("-ksp_rtol 0x1p-3", "-ksp_rtol takes a finite number");
  expect("-pc_type nonsense", "-pc_type takes one of none, jacobi,");
  expect("-ksp_type ../../x", "-ksp_type takes one of cg, gmres,");
  expect("-pc_factor_mat_solver_type superlu_dist", "one of petsc, mumps");
  expect("-pc_hypre_type euclid", "-pc_hypre_type takes one of boomeramg, not 'euclid'");  // reads ./database
  expect("-pc_hypre_boomeramg_smooth_type Euclid", "not 'Euclid'");
  expect("-ksp_gmres_restart 100000", "-ksp_gmres_restart takes an integer in [1, 200]");
  expect("-pc_gamg_threshold 0.1,abc", "-pc_gamg_threshold takes finite numbers in [-1, 0.1] separated by commas");
  expect("-pc_gamg_threshold 0.1,", "-pc_gamg_threshold takes finite numbers");
  expect("-ksp_initial_guess_nonzero maybe", "-ksp_initial_guess_nonzero takes no value or a boolean");
  expect("-mat_mumps_icntl_7 x", "-mat_mumps_icntl_7 takes an integer");
  expect("ksp_monitor", "'ksp_monitor' is not a PETSc option name");
  expect("-ksp_rtol 1e-6 1e-7", "'1e-7' is not a PETSc option name");
  expect("-ksp_rtol 1e-6 -ksp_rtol 1e-7", "-ksp_rtol is given twice");
  expect("-ksp_monitor -KSP_MONITOR", "-KSP_MONITOR is given twice");
  // Choices compare as PETSc compares them, without case.
  EXPECT_EQ(parse_config_petsc_options("-pc_type GAMG -pc_hypre_boomeramg_relax_type_all sor/jacobi").size(), 2u);
  EXPECT_EQ(parse_config_petsc_options("-ksp_initial_guess_nonzero FALSE -ksp_rtol +1e-3").size(), 2u);
}

TEST(ConfigPetscOptions, OptionsForSystemsOfPdesAreRefused) {
  // hypre crashes (SIGSEGV) when the number of unknowns is no multiple of numfunctions.
  for (const char* option : {"-pc_hypre_boomeramg_nodal_coarsen 1", "-pc_hypre_boomeramg_numfunctions 2",
                             "-pc_hypre_boomeramg_vec_interp_variant 3"}) {
    const std::string name = std::string(option).substr(0, std::string(option).find(' '));
    EXPECT_NE(refusal(option).find(name + " is not an option a config may set"), std::string::npos) << refusal(option);
  }
}

TEST(ConfigPetscOptions, OptionsCannotMakeAFactorizationOrGrowMemoryAndWorkWithAValue) {
  // The memory check knows solver.pc only: no factorization by option, under any prefix.
  for (const char* option : {"-pc_type lu", "-pc_type cholesky", "-pc_type icc", "-sub_pc_type lu",
                             "-mg_coarse_pc_type cholesky", "-mg_levels_pc_type icc", "-PC_TYPE LU"}) {
    const std::string msg = refusal(option);
    EXPECT_NE(msg.find("takes one of none, jacobi, pbjacobi, bjacobi, asm, sor, eisenstat, ilu, gamg, hypre, not"),
              std::string::npos)
        << option << ": " << msg;
  }
  // Options that size an allocation or make a factorization out of multigrid, or break the
  // matrix iga-run still needs (in-place factorization), or need libraries that may be missing.
  for (const char* option : {"-mat_mumps_icntl_23 100000", "-mat_mumps_icntl_28 2", "-mat_mumps_icntl_29 2",
                             "-pc_mg_levels 1", "-pc_hypre_boomeramg_max_levels 2", "-pc_factor_in_place", "-pc_asm_blocks 1024",
                             "-sub_pc_factor_in_place"}) {
    const std::string name = std::string(option).substr(0, std::string(option).find(' '));
    EXPECT_NE(refusal(option).find(name + " is not an option a config may set"), std::string::npos) << refusal(option);
  }
  const auto expect = [](const std::string& options, const std::string& text) {
    const std::string msg = refusal(options);
    EXPECT_NE(msg.find(text), std::string::npos) << options << ": " << msg;
  };
  expect("-pc_factor_levels 4", "-pc_factor_levels takes an integer in [0, 3], not '4'");
  expect("-sub_pc_factor_levels 20", "-sub_pc_factor_levels takes an integer in [0, 3]");
  expect("-pc_factor_fill 11", "-pc_factor_fill takes a finite number in [1, 10]");
  expect("-sub_pc_factor_fill 100", "-sub_pc_factor_fill takes a finite number in [1, 10]");
  expect("-pc_factor_mat_ordering_type natural", "-pc_factor_mat_ordering_type takes one of nd, qmd");
  expect("-pc_bjacobi_blocks 1025", "-pc_bjacobi_blocks takes an integer in [1, 1024]");
  expect("-pc_bjacobi_local_blocks 5000", "-pc_bjacobi_local_blocks takes an integer in [1, 1024]");
  expect("-pc_asm_overlap 3", "-pc_asm_overlap takes an integer in [0, 2]");
  expect("-ksp_gmres_restart 1000", "-ksp_gmres_restart takes an integer in [1, 200], not '1000'");
  expect("-ksp_lgmres_augment 31", "-ksp_lgmres_augment takes an integer in [0, 30]");
  expect("-mat_mumps_icntl_14 1000000", "-mat_mumps_icntl_14 takes an integer in [0, 100], not '1000000'");
  expect("-mat_mumps_icntl_10 -1000000", "-mat_mumps_icntl_10 takes an integer in [-10, 10], not '-1000000'");
  expect("-mat_mumps_icntl_10 11", "-mat_mumps_icntl_10 takes an integer in [-10, 10]");
  expect("-mat_mumps_icntl_4 5", "-mat_mumps_icntl_4 takes an integer in [0, 4]");
  expect("-mat_mumps_cntl_1 2", "-mat_mumps_cntl_1 takes a finite number in [0, 1]");
  expect("-pc_gamg_coarse_eq_limit 1000000000", "-pc_gamg_coarse_eq_limit takes an integer in [1, 10000]");
  expect("-pc_gamg_threshold 0.01,0.5", "-pc_gamg_threshold takes finite numbers in [-1, 0.1] separated by commas");
  expect("-pc_gamg_agg_nsmooths 3", "-pc_gamg_agg_nsmooths takes an integer in [0, 2]");
  expect("-pc_gamg_square_graph 100", "-pc_gamg_square_graph takes an integer in [0, 2]");
  expect("-pc_hypre_boomeramg_max_coarse_size 1000000000", "takes an integer in [1, 1000]");
  expect("-pc_hypre_boomeramg_min_coarse_size 1000000000", "takes an integer in [1, 1000]");
  // Counts that multiply the work of every iteration.
  expect("-pc_sor_its 21", "-pc_sor_its takes an integer in [1, 20]");
  expect("-pc_sor_lits 1000", "-pc_sor_lits takes an integer in [1, 20]");
  expect("-pc_hypre_boomeramg_max_iter 11", "takes an integer in [1, 10]");
  expect("-pc_hypre_boomeramg_grid_sweeps_all 21", "takes an integer in [1, 20]");
  expect("-pc_mg_multiplicative_cycles 11", "takes an integer in [1, 10]");
  expect("-mg_levels_ksp_max_it 101", "-mg_levels_ksp_max_it takes an integer in [0, 100]");
  expect("-sub_ksp_max_it 100000", "-sub_ksp_max_it takes an integer in [0, 100]");
  expect("-ksp_pc_side symmetric", "-ksp_pc_side takes one of left, right");  // gmres + eisenstat crashes
  // The bounds themselves pass; the outer solve keeps the full iteration limit.
  EXPECT_EQ(parse_config_petsc_options("-sub_pc_type ilu -sub_pc_factor_levels 3 -sub_pc_factor_fill 10 "
                                       "-pc_bjacobi_blocks 1024 -ksp_gmres_restart 200 -mat_mumps_icntl_14 100 "
                                       "-mat_mumps_icntl_10 -10 -mg_levels_ksp_max_it 100 -ksp_max_it 100000 "
                                       "-ksp_chebyshev_eigenvalues 0.1,2.5")
                .size(),
            10u);
}

TEST(ConfigPetscOptions, ConfigErrorsNameTheFilePlaceAndTheOption) {
  if (!petsc_available()) GTEST_SKIP() << "built without PETSc";
  for (const auto& [options, name] : {std::pair{"-log_view :/tmp/x.txt", "-log_view"},
                                      std::pair{"-ksp_max_it abc", "-ksp_max_it"},
                                      std::pair{"-ksp_view ascii:v.txt", "-ksp_view"}}) {
    const std::string msg = test::input_error(
        [&] { parse("solver:\n  type: petsc\n  options: \"" + std::string(options) + "\"\n"); });
    EXPECT_NE(msg.find("s.yaml:3:"), std::string::npos) << msg;
    EXPECT_NE(msg.find("solver.options"), std::string::npos) << msg;
    EXPECT_NE(msg.find(name), std::string::npos) << msg;
  }
  const Parsed ok = parse("solver:\n  type: petsc\n  options: \"-ksp_monitor -pc_gamg_threshold 0.05\"\n");
  EXPECT_EQ(ok.petsc.options, "-ksp_monitor -pc_gamg_threshold 0.05");
  EXPECT_NE(ok.petsc.options_where.find("s.yaml:3:"), std::string::npos) << ok.petsc.options_where;
}

TEST(ConfigPetscOptions, TheAllowListIsDocumented) {
  std::ifstream in(std::filesystem::path(IGA_SOURCE_DIR) / "docs/parallel.md");
  std::stringstream text;
  text << in.rdbuf();
  const std::string doc = text.str();
  for (const std::string& name : config_petsc_option_names())
    EXPECT_NE(doc.find("`" + name + "`"), std::string::npos) << name << " is not listed in docs/parallel.md";
  for (const std::string& prefix : config_petsc_option_prefixes())
    EXPECT_NE(doc.find("`-" + prefix + "`"), std::string::npos) << prefix << " is not listed in docs/parallel.md";
}

}  // namespace
}  // namespace iga
