#pragma once
// Helpers shared by tests: build spaces and problems from YAML text, as a user's config would.

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <Eigen/Sparse>
#include <cstdio>
#include <random>
#include <filesystem>
#include <string>
#include <vector>

#include "config/config_node.hpp"
#include "output/study_outputs.hpp"
#include "solver/problem.hpp"
#include "solver/solve_problem.hpp"
#include "solver/study.hpp"
#include "spaces/space_factory.hpp"
#include "tests/support/scratch_files.hpp"

namespace iga::test {

/// A space from `domain:` and `space:` YAML snippets, refined `level` times.
inline SpacePtr space_from_yaml(const std::string& yaml, int level = 0) {
  const ConfigNode root = ConfigNode::load_string(yaml, "test.yaml");
  return make_space(root["domain"], root["space"], level);
}

/// n numbers uniform in [−1, 1] from `seed` (random coefficients or weights, the same on every run).
inline Eigen::VectorXd random_vector(int n, unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::VectorXd v(n);
  for (int i = 0; i < n; ++i) v(i) = u(gen);
  return v;
}

/// tridiag(−1, d, −1), n x n, both triangles stored, compressed.
inline SparseMatrix tridiagonal(int n, double d) {
  std::vector<Eigen::Triplet<double>> entries;
  for (int i = 0; i < n; ++i) {
    entries.emplace_back(i, i, d);
    if (i + 1 < n) {
      entries.emplace_back(i, i + 1, -1.0);
      entries.emplace_back(i + 1, i, -1.0);
    }
  }
  SparseMatrix t(n, n);
  t.setFromTriplets(entries.begin(), entries.end());
  t.makeCompressed();
  return t;
}

inline ProblemSpec problem_from_yaml(const std::string& yaml) {
  return parse_problem(ConfigNode::load_string(yaml, "test.yaml")["problem"]);
}

/// Rates between the last two levels of a study; h2 is 0 when the H2 error is not measured.
struct Rates {
  double l2 = 0, h1 = 0, h2 = 0;
};

/// The config's problem solved on its space at `level` (CHOLMOD): errors, DOFs, timings.
inline LevelResult level_result(const std::string& yaml, int level) {
  return solve_problem(*space_from_yaml(yaml, level), problem_from_yaml(yaml), SolverKind::cholmod).result;
}

/// Errors below the given bounds (a reproduced solution: the bounds are round-off's).
inline void expect_errors_below(const LevelResult& r, double l2, double h1, double h2) {
  EXPECT_LT(*r.l2, l2) << "L2 error";
  EXPECT_LT(*r.h1, h1) << "H1 error";
  EXPECT_LT(*r.h2, h2) << "H2 error";
}

/// The rates r within `tolerance` of the expected l2 / h1 / h2 orders (a failure names the norm).
inline void expect_rates(const Rates& r, double l2, double h1, double h2, double tolerance = 0.3) {
  EXPECT_NEAR(r.l2, l2, tolerance) << "L2 rate";
  EXPECT_NEAR(r.h1, h1, tolerance) << "H1 rate";
  EXPECT_NEAR(r.h2, h2, tolerance) << "H2 rate";
}

/// Solve the config's problem on levels 0..levels-1 (printing each row, so a failing rate can be
/// read off the test log) and return the rates between the last two levels.
inline Rates last_rates(const std::string& yaml, int levels) {
  const ProblemSpec problem = problem_from_yaml(yaml);
  std::vector<LevelResult> rows;
  for (int level = 0; level < levels; ++level) {
    const SpacePtr space = space_from_yaml(yaml, level);
    rows.push_back(solve_problem(*space, problem, SolverKind::cholmod).result);
    const LevelResult& b = rows.back();
    std::printf("level %d elements %d dofs %d h %.4f  L2 %.3e H1 %.3e H2 %.3e\n", level, space->num_elements(),
                space->dimension(), b.h, *b.l2, *b.h1, b.h2.value_or(0.0));
  }
  const LevelResult &a = rows[levels - 2], &b = rows[levels - 1];
  Rates r{*rate(a.l2, b.l2, a.h, b.h), *rate(a.h1, b.h1, a.h, b.h), 0.0};
  if (a.h2 && b.h2) r.h2 = *rate(a.h2, b.h2, a.h, b.h);
  return r;
}

/// Parses and runs the study of a whole config text (quietly), writing its output into this test
/// program's scratch folder under `name` (one folder per process, so parallel test cases never
/// share an output directory).
inline StudyResult run_study_from_yaml(const std::string& yaml, const std::string& name) {
  const std::string dir = (scratch_folder() / name).string();
  const StudySettings settings = parse_study(ConfigNode::load_string(yaml, name + ".yaml"), name + ".yaml", 0, dir);
  std::filesystem::create_directories(dir);
  return run_study_with_vtk(settings, dir, [](const std::string&) {});
}

}  // namespace iga::test
