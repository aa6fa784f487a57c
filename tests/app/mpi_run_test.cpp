// `mpirun -np 2 iga-run config.yaml` as a user runs it: one shipped config per space solved with
// PETSc on two ranks writes the convergence table of the serial CHOLMOD run and a .pvtu whose two
// pieces VTK reads back as the serial run's grid, a failure on the ranks ends every rank with
// the right exit code (no hang), a config's PETSc options are held to the allow-list, and options
// files of the working directory are never read.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <thread>
#include <sstream>
#include <string>
#include <vector>

#include "solver/petsc_settings.hpp"
#include "tests/support/scratch_files.hpp"

#ifdef IGA_WITH_PETSC  // VTK's parallel XML reader is linked with the PETSc build
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPUnstructuredGridReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <algorithm>
#endif

namespace fs = std::filesystem;

namespace {

struct RunResult {
  int exit_code;
  std::string err;
};

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Run iga-run with `args`, under `mpirun -np ranks` when ranks > 0 (as root too: CI runs as root;
/// oversubscribed: CI machines may have one core), in `folder` if given.
/// `environment`: a prefix of the launch ("env -u OMP_NUM_THREADS ").
RunResult run(int ranks, const std::string& args, const fs::path& folder = {}, const std::string& environment = {}) {
  const fs::path err = iga::test::scratch_folder() / "stderr.txt";
  std::string launcher;
  if (!folder.empty()) launcher = "cd " + folder.string() + " && ";
  launcher += environment;
  if (ranks > 0) launcher += std::string(IGA_MPIEXEC) + " --allow-run-as-root --oversubscribe -np " + std::to_string(ranks) + " ";
  const std::string cmd = launcher + IGA_RUN_BINARY + " " + args + " >/dev/null 2>" + err.string();
  const int status = std::system(cmd.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(err)};
}

/// The shipped config with its solver: section replaced (and no plot; no VTK unless asked for). An
/// output block keeps its functionals.
fs::path config_with_solver(const std::string& config, const std::string& solver, const std::string& name,
                            bool vtk = false) {
  std::ifstream in(std::string(IGA_SOURCE_DIR) + "/configs/" + config + ".yaml");
  const std::string vtk_plot = std::string("vtk: ") + (vtk ? "true" : "false") + ", plot: false";
  std::string line, text;
  bool in_block = false, output_given = false;
  while (std::getline(in, line)) {
    if (line.rfind("solver:", 0) == 0) continue;
    if (line.rfind("output:", 0) == 0) {
      in_block = line.find('{') == std::string::npos;  // a block: its keys follow, indented
      if (in_block) {
        text += "output:\n  vtk: " + std::string(vtk ? "true" : "false") + "\n  plot: false\n";
        output_given = true;
      }
      continue;
    }
    if (in_block && line.rfind("  ", 0) == 0) {
      for (const char* key : {"  vtk:", "  plot:", "  directory:"})
        if (line.rfind(key, 0) == 0) line.clear();
      if (!line.empty()) text += line + "\n";
      continue;
    }
    in_block = false;
    text += line + "\n";
  }
  if (!output_given) text += "output: {" + vtk_plot + "}\n";
  text += "solver: " + solver + "\n";
  return iga::test::scratch_file(name + ".yaml", text);
}

/// Columns of convergence.csv compared between runs: dofs, the errors, the energy and the
/// functionals (by the header's names), empty cells as written.
std::vector<std::vector<std::pair<std::string, std::string>>> compared_rows(const fs::path& csv) {
  std::ifstream in(csv);
  std::string line;
  std::vector<std::string> names;
  std::getline(in, line);
  {
    std::stringstream s(line);
    for (std::string cell; std::getline(s, cell, ',');) names.push_back(cell);
  }
  const auto compared = [&](std::size_t k) {
    const std::string& n = names[k];
    if (n == "dofs" || n == "l2" || n == "h1" || n == "h2" || n == "energy") return true;
    // The functionals come after the fixed columns, each with its order.
    const auto last_fixed = std::find(names.begin(), names.end(), "rate_difference_h2");
    return static_cast<std::ptrdiff_t>(k) > last_fixed - names.begin() && n.rfind("order_", 0) != 0;
  };
  std::vector<std::vector<std::pair<std::string, std::string>>> rows;
  while (std::getline(in, line)) {
    std::stringstream s(line);
    std::vector<std::pair<std::string, std::string>> row;
    std::size_t k = 0;
    for (std::string cell; k < names.size(); ++k) {
      if (!std::getline(s, cell, ',')) cell.clear();
      if (compared(k)) row.emplace_back(names[k], cell);
    }
    rows.push_back(row);
  }
  return rows;
}

struct Case {
  const char* config;
  int levels;
  double tolerance;  ///< relative: 1e-8 for CG (rtol 1e-12), 1e-10 for MUMPS (round-off, h⁻⁴ amplified)
  const char* petsc = "{type: petsc}";  ///< the solver of the two-rank run
};

class TwoRanks : public ::testing::TestWithParam<Case> {};

TEST_P(TwoRanks, WriteTheErrorsOfTheSerialCholmodRun) {
  if (!iga::petsc_available()) GTEST_SKIP() << "built without PETSc";
  const Case c = GetParam();
  const fs::path dir = iga::test::scratch_folder() / c.config;
  const std::string levels = " --quiet --levels " + std::to_string(c.levels) + " --output ";
  ASSERT_EQ(run(0, config_with_solver(c.config, "{type: cholmod}", std::string(c.config) + "-serial").string() + levels +
                       (dir / "serial").string()).exit_code, 0);
  const RunResult parallel =
      run(2, config_with_solver(c.config, c.petsc, std::string(c.config) + "-petsc").string() + levels +
                 (dir / "np2").string());
  ASSERT_EQ(parallel.exit_code, 0) << parallel.err;
  const auto serial_rows = compared_rows(dir / "serial" / "convergence.csv");
  const auto parallel_rows = compared_rows(dir / "np2" / "convergence.csv");
  ASSERT_EQ(serial_rows.size(), static_cast<std::size_t>(c.levels));
  ASSERT_EQ(parallel_rows.size(), serial_rows.size());
  for (std::size_t l = 0; l < serial_rows.size(); ++l) {
    ASSERT_EQ(parallel_rows[l].size(), serial_rows[l].size());
    for (std::size_t k = 0; k < serial_rows[l].size(); ++k) {
      const auto& [name, b_text] = serial_rows[l][k];
      const std::string& a_text = parallel_rows[l][k].second;
      // a(u, u) comes from the matrix the direct solvers keep for their refinement; a Krylov
      // solve (the second-order cases' CG + GAMG) keeps no unreduced matrix and writes none.
      if (name == "energy" && a_text.empty()) continue;
      ASSERT_EQ(a_text.empty(), b_text.empty()) << c.config << " level " << l << " column " << name;
      if (b_text.empty()) continue;
      const double a = std::stod(a_text), b = std::stod(b_text);
      if (name == "dofs") {
        EXPECT_EQ(a, b) << "dofs of level " << l;
        continue;
      }
      // Where the exact solution lies in the space the errors are round-off (1e-18 .. 1e-15 for
      // these O(1) solutions): compared absolutely there.
      EXPECT_LE(std::abs(a - b), c.tolerance * std::abs(b) + 1e-13) << c.config << " level " << l << " column " << name;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(EverySpace, TwoRanks,
                         ::testing::Values(Case{"bspline-poisson", 4, 1e-8}, Case{"ws4-biharmonic", 2, 1e-10},
                                           // Every element its own shape class: each rank builds
                                           // the extractions of its part only. MUMPS: CG's
                                           // tolerance on this WS4 matrix leaves H2 1e-8 apart.
                                           Case{"ws4-poisson-perturbed", 2, 1e-10, "{type: petsc, pc: mumps}"},
                                           Case{"tmesh-poisson-trig", 3, 1e-8}, Case{"g1-biharmonic-3patch", 3, 1e-10},
                                           Case{"g1_4split-biharmonic-pentagon", 2, 1e-10},
                                           // Surfaces: the PETSc path refines with the element matrices
                                           // in double-double, the serial one with the matrix in double
                                           // (2.8e-10 apart for the cube's plate at level 1, as before
                                           // the ranks worked on parts).
                                           Case{"g1_4split-surface-cube", 2, 1e-9},
                                           Case{"surface-biharmonic-open-cube", 2, 1e-9},
                                           // A free shell (six rigid motions pinned, point loads;
                                           // the whole space on each rank): the energy and the
                                           // displacements under the loads (4e-12 apart at level 1).
                                           Case{"shell-pinched-hemisphere", 2, 1e-9}),
                         [](const ::testing::TestParamInfo<Case>& info) {
                           std::string name = info.param.config;
                           for (char& ch : name)
                             if (ch == '-') ch = '_';
                           return name;
                         });

#ifdef IGA_WITH_PETSC
/// The global element numbers of a grid's cells (cell field `element`), sorted.
std::vector<int> sorted_elements(vtkUnstructuredGrid* grid) {
  vtkDataArray* element = grid->GetCellData()->GetArray("element");
  std::vector<int> out;
  if (!element) return out;
  for (vtkIdType c = 0; c < element->GetNumberOfTuples(); ++c) out.push_back(static_cast<int>(element->GetTuple1(c)));
  std::sort(out.begin(), out.end());
  return out;
}

class TwoRanksVtk : public ::testing::TestWithParam<const char*> {};

// Each rank writes its elements as one piece; VTK's parallel reader puts them together into the
// serial run's cells (the same cells, each element once), and the .pvd collection names the .pvtu.
TEST_P(TwoRanksVtk, ThePvtuReadsBackAsTheSerialGridWithOnePiecePerRank) {
  if (!iga::petsc_available()) GTEST_SKIP() << "built without PETSc";
  const std::string config = GetParam();
  const fs::path dir = iga::test::scratch_folder() / (config + "-vtk");
  const std::string args = " --quiet --levels 2 --output ";
  ASSERT_EQ(run(0, config_with_solver(config, "{type: cholmod}", config + "-vtk-serial", true).string() + args +
                       (dir / "serial").string()).exit_code, 0);
  const RunResult parallel =
      run(2, config_with_solver(config, "{type: petsc}", config + "-vtk-petsc", true).string() + args + (dir / "np2").string());
  ASSERT_EQ(parallel.exit_code, 0) << parallel.err;
  for (int level = 0; level < 2; ++level) {
    const std::string stem = "solution_" + std::to_string(level);
    vtkNew<vtkXMLUnstructuredGridReader> serial;
    serial->SetFileName((dir / "serial" / (stem + ".vtu")).c_str());
    serial->Update();
    vtkNew<vtkXMLPUnstructuredGridReader> whole;
    whole->SetFileName((dir / "np2" / (stem + ".pvtu")).c_str());
    whole->Update();
    EXPECT_EQ(whole->GetNumberOfPieces(), 2) << stem;
    const vtkIdType cells = serial->GetOutput()->GetNumberOfCells();
    ASSERT_GT(cells, 0);
    EXPECT_EQ(whole->GetOutput()->GetNumberOfCells(), cells) << stem;
    EXPECT_EQ(sorted_elements(whole->GetOutput()), sorted_elements(serial->GetOutput())) << stem;
    vtkIdType piece_cells = 0;
    for (int rank = 0; rank < 2; ++rank) {
      const fs::path piece = dir / "np2" / (stem + "_" + std::to_string(rank) + ".vtu");
      ASSERT_TRUE(fs::exists(piece)) << piece;
      vtkNew<vtkXMLUnstructuredGridReader> reader;
      reader->SetFileName(piece.c_str());
      reader->Update();
      EXPECT_GT(reader->GetOutput()->GetNumberOfCells(), 0) << piece;  // both ranks own elements
      piece_cells += reader->GetOutput()->GetNumberOfCells();
    }
    EXPECT_EQ(piece_cells, cells) << stem;
    EXPECT_FALSE(fs::exists(dir / "np2" / (stem + ".vtu")));
  }
  EXPECT_NE(slurp(dir / "np2" / "solution.pvd").find("file=\"solution_1.pvtu\""), std::string::npos);
  for (const auto& entry : fs::directory_iterator(dir / "np2"))  // no scratch files left behind
    EXPECT_NE(entry.path().filename().string().front(), '.') << entry.path();
}

// Lagrange cells (B-splines) and linear sub-cells of macro-elements (G1).
INSTANTIATE_TEST_SUITE_P(TwoSpaces, TwoRanksVtk, ::testing::Values("bspline-poisson", "g1-biharmonic-3patch"),
                         [](const ::testing::TestParamInfo<const char*>& info) {
                           std::string name = info.param;
                           for (char& ch : name)
                             if (ch == '-') ch = '_';
                           return name;
                         });
#endif

/// summary.json's processes block: (ranks, threads_per_rank).
std::pair<int, int> processes(const fs::path& summary) {
  const std::string text = slurp(summary);
  std::smatch m;
  if (!std::regex_search(text, m, std::regex(R"("ranks":\s*(\d+),\s*"threads_per_rank":\s*(\d+))"))) return {0, 0};
  return {std::stoi(m[1]), std::stoi(m[2])};
}

TEST(TwoRanksThreads, EachRankTakesItsShareOfTheCoresUnlessTheUserSaysOtherwise) {
  if (!iga::petsc_available()) GTEST_SKIP() << "built without PETSc";
  const fs::path cfg = config_with_solver("bspline-poisson", "{type: petsc}", "threads");
  const fs::path dir = iga::test::scratch_folder() / "threads";
  const std::string args = cfg.string() + " --quiet --levels 1 --output ";
  // OpenMP's default would be one thread per core in each rank: 2 × cores threads on the cores.
  ASSERT_EQ(run(2, args + (dir / "default").string(), {}, "env -u OMP_NUM_THREADS ").exit_code, 0);
  const auto [ranks, threads] = processes(dir / "default" / "summary.json");
  EXPECT_EQ(ranks, 2);
  const int cores = static_cast<int>(std::thread::hardware_concurrency());
  // At most the node's cores per rank (fewer when mpirun binds each rank to fewer cores).
  EXPECT_GE(threads, 1);
  EXPECT_LE(threads, std::max(1, cores / 2));
  ASSERT_EQ(run(2, args + (dir / "option").string() + " --threads 3").exit_code, 0);
  EXPECT_EQ(processes(dir / "option" / "summary.json"), std::make_pair(2, 3));
  ASSERT_EQ(run(2, args + (dir / "environment").string(), {}, "env OMP_NUM_THREADS=2 ").exit_code, 0);
  EXPECT_EQ(processes(dir / "environment" / "summary.json"), std::make_pair(2, 2));
}

TEST(TwoRanksFailures, AnUnconvergedSolveIsExitOneOnEveryRankWithTheReason) {
  if (!iga::petsc_available()) GTEST_SKIP() << "built without PETSc";
  const fs::path cfg = config_with_solver("bspline-poisson", "{type: petsc, pc: ilu, max_iterations: 2}", "diverging");
  const RunResult r = run(2, cfg.string() + " --quiet --levels 3 --output " + (iga::test::scratch_folder() / "d").string());
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("DIVERGED_ITS after 2 iterations"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(iga::test::scratch_folder() / "d"));
}

TEST(TwoRanksFailures, AnOutputErrorOfRankZeroReachesTheOtherRank) {
  if (!iga::petsc_available()) GTEST_SKIP() << "built without PETSc";
  const fs::path cfg = config_with_solver("bspline-poisson", "{type: petsc}", "bad-output");
  const RunResult r = run(2, cfg.string() + " --quiet --levels 2 --output /proc/iga-run-test-output");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("--output"), std::string::npos) << r.err;
}

TEST(TwoRanksFailures, AnUnusedPetscOptionIsReported) {
  if (!iga::petsc_available()) GTEST_SKIP() << "built without PETSc";
  // A hypre parameter with GAMG: allowed in a config, but nothing reads it.
  const fs::path cfg =
      config_with_solver("bspline-poisson", "{type: petsc, options: \"-pc_hypre_boomeramg_max_iter 2\"}", "unused");
  const RunResult r = run(2, cfg.string() + " --quiet --levels 1 -pc_gamg_thresold 0.1 --output " +
                                 (iga::test::scratch_folder() / "u").string());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("PETSc option -pc_hypre_boomeramg_max_iter 2 was not used"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("PETSc option -pc_gamg_thresold 0.1 was not used"), std::string::npos) << r.err;
}

TEST(TwoRanksFailures, AConfigOptionThatWritesAFileIsRefusedOnEveryRankBeforeAnyWork) {
  if (!iga::petsc_available()) GTEST_SKIP() << "built without PETSc";
  const fs::path log = iga::test::scratch_folder() / "log_view.txt";
  const fs::path cfg =
      config_with_solver("bspline-poisson", "{type: petsc, options: \"-log_view :" + log.string() + "\"}", "log-view");
  const RunResult r = run(2, cfg.string() + " --quiet --levels 1 --output " + (iga::test::scratch_folder() / "l").string());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("solver.options: -log_view is not an option a config may set"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("PETSC ERROR"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(log));
  EXPECT_FALSE(fs::exists(iga::test::scratch_folder() / "l"));
}

TEST(TwoRanksFailures, AnOptionPetscRefusesWhenSettingUpIsAnInputErrorWithoutPetscsBanner) {
  if (!iga::petsc_available()) GTEST_SKIP() << "built without PETSc";
  // Allowed, but PETSc's own ILU is sequential: PETSc finds out when it sets it up.
  const fs::path cfg = config_with_solver("bspline-poisson", "{type: petsc, options: \"-pc_type ilu\"}", "ilu");
  const RunResult r = run(2, cfg.string() + " --quiet --levels 1 --output " + (iga::test::scratch_folder() / "i").string());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("solver.options"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("PETSc could not set up cg + ilu: Could not locate a solver type for factorization type ILU"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(r.err.find("PETSC ERROR"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(iga::test::scratch_folder() / "i"));
}

TEST(TwoRanksPetscrc, OptionsFilesOfTheWorkingDirectoryAreNotRead) {
  if (!iga::petsc_available()) GTEST_SKIP() << "built without PETSc";
  // Under mpirun PETSc starts before the config is read: the files would act on every run.
  const fs::path dir = iga::test::scratch_folder() / "downloaded";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path cfg = config_with_solver("bspline-poisson", "{type: petsc}", "petscrc");
  std::ofstream(dir / ".petscrc") << "-log_view :" << (dir / "log.txt").string() << "\n-history "
                                  << (dir / "history.txt").string() << "\n";
  std::ofstream(dir / "petscrc") << "-malloc_dump " << (dir / "dump.txt").string() << "\n";
  const RunResult r = run(2, cfg.string() + " --quiet --levels 1 --output " + (dir / "results").string(), dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir / "results" / "convergence.csv")) << r.err;
  for (const char* file : {"log.txt", "history.txt", "dump.txt"})
    EXPECT_FALSE(fs::exists(dir / file)) << file << ": an options file of the working directory was read";
}

}  // namespace
