// The eigen comparison of spaces (`spaces:` with problem.eigen: comparison.txt and comparison.svg):
// per space and level, the DOFs and the largest relative error over the eigenvalues that have a
// reference. Built from EigenLevel values with known errors, through eigen_rows as the study does.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "output/eigen_plot.hpp"
#include "output/eigen_report.hpp"

namespace iga {
namespace {

/// A level whose eigenvalues are reference · (1 + errors[i]).
EigenLevel level_with_errors(int level, int dofs, const std::vector<double>& reference, const std::vector<double>& errors) {
  EigenLevel l;
  l.level = level;
  l.h = 1.0 / (1 << level);
  l.dofs = dofs;
  l.values.resize(static_cast<Eigen::Index>(errors.size()));
  for (std::size_t i = 0; i < errors.size(); ++i) l.values(static_cast<Eigen::Index>(i)) = reference[i] * (1 + errors[i]);
  return l;
}

TEST(EigenComparison, LargestRelativeErrorPerLevelOverTheIndicesWithReferences) {
  // Three eigenvalues, references for the first two only: the third (error 0.5 if it had one) must
  // not count. The largest error is λ₂'s on level 0 and λ₁'s on level 1.
  const std::vector<double> exact = {2.0, 5.0};
  const std::vector<double> values = {2.0, 5.0, 8.0};
  const std::vector<EigenLevel> levels = {level_with_errors(0, 100, values, {1e-3, 4e-3, 0.5}),
                                          level_with_errors(1, 400, values, {2e-4, 1e-4, 0.5})};
  const std::vector<EigenRow> rows = eigen_rows(levels, exact);
  const auto worst = worst_relative_errors(rows);
  ASSERT_EQ(worst.size(), 2u);
  EXPECT_EQ(worst[0].first, 100);
  EXPECT_NEAR(worst[0].second, 4e-3, 1e-15);
  EXPECT_EQ(worst[1].first, 400);
  EXPECT_NEAR(worst[1].second, 2e-4, 1e-15);

  // The text table: one line per space and level, with those numbers.
  const std::string table = format_eigen_comparison({{"bspline-p3", rows}, {"ws4-p4", rows}});
  char line[80];
  std::snprintf(line, sizeof line, "%-16s %8d %12.3e\n", "ws4-p4", 400, 2e-4);
  EXPECT_NE(table.find(line), std::string::npos) << table;
  std::snprintf(line, sizeof line, "%-16s %8d %12.3e\n", "bspline-p3", 100, 4e-3);
  EXPECT_NE(table.find(line), std::string::npos) << table;
  EXPECT_EQ(std::count(table.begin(), table.end(), '\n'), 2 + 4);  // title, header, 2 spaces × 2 levels
}

TEST(EigenComparison, NoReferencesNoPoints) {
  const std::vector<EigenLevel> levels = {level_with_errors(0, 100, {2.0}, {1e-3})};
  EXPECT_TRUE(worst_relative_errors(eigen_rows(levels, {})).empty());
}

}  // namespace
}  // namespace iga
