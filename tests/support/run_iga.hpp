#pragma once
// The iga-run program run as a user runs it (the test programs get IGA_RUN_BINARY from CMake):
// its exit code, stdout and stderr; configs written into the test program's scratch folder.

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "tests/support/scratch_files.hpp"

namespace iga::test {

struct RunResult {
  int exit_code;  ///< -1 if the program ended by a signal
  std::string out, err;
};

inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// `iga-run ARGS` run from the folder `cwd` (the test's own when empty), through the shell (ARGS
/// may hold redirections or quotes). A config's relative output.directory is below `cwd`.
inline RunResult run_iga_in(const std::filesystem::path& cwd, const std::string& args) {
  const std::filesystem::path out = scratch_folder() / "stdout.txt", err = scratch_folder() / "stderr.txt";
  const std::string cd = cwd.empty() ? "" : "cd '" + cwd.string() + "' && ";
  const std::string cmd = cd + std::string(IGA_RUN_BINARY) + " " + args + " > " + out.string() + " 2> " + err.string();
  const int status = std::system(cmd.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(out), slurp(err)};
}

/// `iga-run ARGS` from the test's working directory.
inline RunResult run_iga(const std::string& args) { return run_iga_in({}, args); }

inline std::filesystem::path write_config(const std::string& name, const std::string& text) {
  const std::filesystem::path p = scratch_folder() / name;
  std::ofstream(p) << text;
  return p;
}

/// A valid config that runs in milliseconds: quadratic B-splines, Poisson, two levels.
inline constexpr const char* kSmallPoissonConfig = R"yaml(problem:
  pde: poisson
  exact: "x*y + sin(x)"
  boundary: {all: dirichlet}
domain: {type: rectangle, min: [0, 0], max: [1, 1]}
space: {type: bspline, degree: 2, elements: [2, 2]}
refinement: {levels: 2}
)yaml";

}  // namespace iga::test
