/// @file
/// The command line beyond running one config: --list, check, --threads, --help, the error prefix
/// of command-line mistakes, several configs compared in one run, and the PETSc options files read
/// at start-up (the user's ~/.petscrc, never one of the working directory).

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <sys/wait.h>

#include "app/catalogue.hpp"
#include "solver/petsc_settings.hpp"
#include "spaces/space_factory.hpp"
#include "tests/support/run_iga.hpp"
#include "tests/support/scratch_files.hpp"

namespace {

using iga::test::RunResult;
using iga::test::run_iga;
using iga::test::run_iga_in;
using iga::test::slurp;
using iga::test::write_config;

namespace fs = std::filesystem;

const char* const kGood = iga::test::kSmallPoissonConfig;

TEST(CommandLine, ListPrintsTheCatalogue) {
  // What the listing holds is checked against the builders in catalogue_test.cpp.
  const RunResult r = run_iga("--list");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, iga::catalogue_text());
  for (const std::string& type : iga::space_types()) EXPECT_NE(r.out.find("  " + type + " "), std::string::npos) << type;
  EXPECT_NE(r.out.find("    graph "), std::string::npos) << "the lift of every planar space";
}

TEST(CommandLine, HelpShowsTheCommands) {
  const RunResult r = run_iga("--help");
  ASSERT_EQ(r.exit_code, 0);
  for (const char* word : {"check", "new SPACE [DOMAIN]", "--list", "--threads", "--levels", "--quiet"})
    EXPECT_NE(r.out.find(word), std::string::npos) << word;
}

TEST(CommandLine, CheckValidatesWithoutWriting) {
  const fs::path out = iga::test::scratch_folder() / "check-out";
  const fs::path good = write_config("check-good.yaml", std::string(kGood) + "output: {directory: check-out}\n");
  RunResult r = run_iga_in(iga::test::scratch_folder(), "check " + good.string());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find(": ok (bspline-p2; poisson, 2 levels)"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(out));
  const fs::path bad = write_config("check-bad.yaml", std::string(kGood) + "outptu: {}\n");
  r = run_iga("check " + bad.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err.rfind("iga-run: error: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("did you mean 'output'"), std::string::npos) << r.err;
}

TEST(CommandLine, MistakesCarryTheErrorPrefix) {
  const fs::path cfg = write_config("prefix.yaml", kGood);
  RunResult r = run_iga(cfg.string() + " --levels abc");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "iga-run: error: --levels: 'abc' is not a number\n");
  r = run_iga(cfg.string() + " --levels 13");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--levels: must be between 1 and 12"), std::string::npos) << r.err;
  r = run_iga(cfg.string() + " --threads 0");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err.rfind("iga-run: error: --threads", 0), 0u) << r.err;
  r = run_iga("--bogus " + cfg.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err.rfind("iga-run: error: ", 0), 0u) << r.err;
  r = run_iga("");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err.rfind("iga-run: error: a config file is required", 0), 0u) << r.err;
}

TEST(CommandLine, ThreadsAndQuiet) {
  const fs::path out = iga::test::scratch_folder() / "threads-out";
  const fs::path cfg = write_config("threads.yaml", kGood);
  const RunResult r = run_iga(cfg.string() + " --threads 1 --quiet --output " + out.string());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_TRUE(fs::exists(out / "convergence.csv"));
  EXPECT_NE(r.out.find("t_space"), std::string::npos);
  EXPECT_NE(r.out.find("t_errors"), std::string::npos);
}

TEST(CommandLine, SeveralConfigsAreOneComparison) {
  const fs::path out = iga::test::scratch_folder() / "compare-out";
  const fs::path a = write_config("a.yaml", kGood);
  const fs::path b = write_config("b.yaml", std::string(kGood).replace(std::string(kGood).find("degree: 2"), 9, "degree: 3"));
  const RunResult r = run_iga(a.string() + " " + b.string() + " --quiet --output " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(out / "bspline-p2" / "convergence.csv"));
  EXPECT_TRUE(fs::exists(out / "bspline-p3" / "convergence.csv"));
  const std::string csv = slurp(out / "comparison.csv");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 1 + 2 * 2) << csv;
  EXPECT_NE(csv.find("\nbspline-p3,1,"), std::string::npos) << csv;
  EXPECT_NE(r.out.find("DOFs and time"), std::string::npos) << r.out;
  EXPECT_GT(fs::file_size(out / "comparison.svg"), 1000u);
}

TEST(CommandLine, PetscReadsTheHomePetscrcButNeverTheWorkingDirectorys) {
  if (!iga::petsc_available()) GTEST_SKIP() << "built without PETSc";
  // A folder of downloaded inputs: a config and options files that would write files there and
  // read /etc/passwd. The user's home holds a harmless ~/.petscrc that must still work.
  const fs::path dir = iga::test::scratch_folder() / "downloaded", home = iga::test::scratch_folder() / "home";
  fs::remove_all(dir);
  fs::remove_all(home);
  fs::create_directories(dir);
  fs::create_directories(home);
  std::ofstream(dir / "petsc.yaml") << kGood << "solver: {type: petsc}\n";
  std::ofstream(dir / ".petscrc") << "-log_view :" << (dir / "log.txt").string() << "\n-history "
                                  << (dir / "history.txt").string() << "\n";
  std::ofstream(dir / "petscrc") << "-malloc_dump " << (dir / "dump.txt").string() << "\n-options_file /etc/passwd\n";
  std::ofstream(home / ".petscrc") << "-ksp_converged_reason\n";
  const fs::path out = iga::test::scratch_folder() / "petscrc-stdout.txt", err = iga::test::scratch_folder() / "petscrc-stderr.txt";
  const std::string cmd = "cd " + dir.string() + " && env -u PETSC_OPTIONS HOME=" + home.string() + " " + IGA_RUN_BINARY +
                          " --quiet petsc.yaml --output results > " + out.string() + " 2> " + err.string();
  const int status = std::system(cmd.c_str());
  const std::string stdout_text = slurp(out), stderr_text = slurp(err);
  ASSERT_TRUE(WIFEXITED(status)) << stderr_text;
  EXPECT_EQ(WEXITSTATUS(status), 0) << stderr_text;
  EXPECT_TRUE(fs::exists(dir / "results" / "convergence.csv")) << stderr_text;
  EXPECT_NE(stdout_text.find("Linear solve converged due to"), std::string::npos) << "~/.petscrc not read:\n" << stdout_text;
  for (const char* file : {"log.txt", "history.txt", "dump.txt"})
    EXPECT_FALSE(fs::exists(dir / file)) << file << ": an options file of the working directory was read";
  EXPECT_EQ(stderr_text.find("root:"), std::string::npos) << stderr_text;
}

}  // namespace
