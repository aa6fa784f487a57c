#pragma once
// Tests that run a case on several MPI ranks: the test binary starts itself again under mpirun with
// a gtest filter, and the variable `ranks_variable` tells the child run how many ranks it was given.

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace iga::test {

/// The rank count the mpirun of rerun_under_mpirun asked for through `ranks_variable` (1 when the
/// test binary was started directly).
inline int expected_ranks(const char* ranks_variable) {
  const char* v = std::getenv(ranks_variable);
  return v && *v ? std::atoi(v) : 1;
}

/// Runs this test binary on `ranks` ranks with `filter`; returns its exit status (-1: no normal exit).
/// As root (CI) and oversubscribed (CI machines may have one core), as tests/app/mpi_run_test.cpp;
/// without the variables Open MPI set in this process if an earlier test started MPI here (mpirun
/// would take itself for a child of this singleton).
inline int rerun_under_mpirun(const char* ranks_variable, int ranks, const std::string& filter) {
  const std::string command =
      "for v in $(env | grep -o '^\\(OMPI\\|PMIX\\|OPAL\\)[A-Za-z0-9_]*'); do unset $v; done; " +
      std::string(ranks_variable) + "=" + std::to_string(ranks) + " mpirun --allow-run-as-root --oversubscribe -np " +
      std::to_string(ranks) + " " + std::filesystem::read_symlink("/proc/self/exe").string() +
      " --gtest_filter=" + filter;
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace iga::test
