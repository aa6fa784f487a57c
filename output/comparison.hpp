#pragma once
/// @file
/// One report across spaces solving one problem: comparison.csv (every level of every space),
/// comparison.svg (error against DOFs and against time, one line per space) and the table of the
/// DOFs and time each space needs to reach given errors.

#include <optional>
#include <string>
#include <vector>

#include "solver/study.hpp"

namespace iga {

/// One space's study within a comparison.
struct ComparedStudy {
  std::string label;  ///< e.g. "bspline-p3" (its results are in a subfolder of that name)
  StudyResult result;
};

/// The error a comparison ranks by: the strongest norm every study measured (H2, else H1, else
/// L2); nullopt when some study has no errors at all.
enum class ComparedNorm { l2, h1, h2 };
std::optional<ComparedNorm> compared_norm(const std::vector<ComparedStudy>& studies);

/// Seconds to compute a level's solution: space, assembly, factorization and solve (not the
/// error norms or files, which measure the result rather than produce it).
double solution_seconds(const LevelResult& row);

void write_comparison_csv(const std::vector<ComparedStudy>& studies, const std::string& filename);

/// For errors 10^k spanning what the studies reached: per space, the first level whose error is
/// at most that, with its DOFs and solution_seconds ("-" where never reached).
std::string format_reach_table(const std::vector<ComparedStudy>& studies, ComparedNorm norm);

/// Error against DOFs (left) and against solution time (right), one line per space.
void plot_comparison(const std::vector<ComparedStudy>& studies, ComparedNorm norm, const std::string& title,
                     const std::string& filename);

}  // namespace iga
