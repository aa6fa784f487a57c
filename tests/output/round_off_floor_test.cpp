/// @file
/// Round-off floor: the level where a cleanly converging error stops decreasing is marked in the
/// table and the CSV and left out of the least-squares rates.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "output/report.hpp"
#include "tests/support/scratch_files.hpp"

namespace iga {
namespace {

/// Levels with h = 2^-(l+1) and L2 error h^4 until level 4 (9.5e-7), then stuck near 1e-6 (round-off).
std::vector<LevelResult> rows_with_floor() {
  std::vector<LevelResult> rows;
  for (int l = 0; l < 7; ++l) {
    LevelResult r;
    r.level = l;
    r.h = std::pow(0.5, l + 1);
    r.dofs = (1 << (2 * l)) * 16;
    r.l2 = l < 5 ? std::pow(r.h, 4) : (l == 5 ? 8e-7 : 1.2e-6);
    r.h1 = std::pow(r.h, 3);  // clean throughout
    rows.push_back(r);
  }
  return rows;
}

TEST(RoundOffFloor, MarksTheLevelsAfterCleanRatesStop) {
  const auto rows = rows_with_floor();
  const RoundOffFloor floor = round_off_levels(rows, false);
  EXPECT_EQ(floor.l2, (std::vector<bool>{false, false, false, false, false, true, true}));
  EXPECT_EQ(floor.h1, std::vector<bool>(7, false));
  // Without the floor levels the fit is the clean rate 4 exactly.
  std::vector<double> h;
  std::vector<std::optional<double>> l2;
  for (const auto& r : rows) h.push_back(r.h), l2.push_back(r.l2);
  EXPECT_NEAR(*least_squares_rate(h, l2, floor.l2), 4.0, 1e-12);
  EXPECT_LT(*least_squares_rate(h, l2), 3.0);  // what including them would claim
}

TEST(RoundOffFloor, PreAsymptoticSlowLevelsAreNotAFloor) {
  // Errors that start slow and then converge: no level is marked.
  std::vector<LevelResult> rows;
  const double e[] = {1.0, 0.9, 0.3, 0.02, 0.0012};
  for (int l = 0; l < 5; ++l) {
    LevelResult r;
    r.level = l, r.h = std::pow(0.5, l), r.dofs = 4 << (2 * l), r.l2 = e[l];
    rows.push_back(r);
  }
  EXPECT_FALSE(round_off_levels(rows, false).any());
}

TEST(RoundOffFloor, TableStarsAndCsvColumns) {
  const auto rows = rows_with_floor();
  const std::string table = format_convergence_table(rows);
  EXPECT_NE(table.find("* round-off floor"), std::string::npos);
  EXPECT_NE(table.find("*"), table.find("* round-off floor"));  // a rate carries the star too
  const std::string file = (test::scratch_folder() / "floor.csv").string();
  write_convergence_csv(rows, file);
  std::ifstream in(file);
  std::string header, line;
  std::getline(in, header);
  EXPECT_EQ(header.rfind("level,h,dofs,l2,h1,h2,rate_l2,rate_h1,rate_h2,t_assemble,t_solve", 0), 0u);
  EXPECT_NE(header.find(",floor_l2,floor_h1,floor_h2"), std::string::npos);
  auto split = [](const std::string& text) {
    std::vector<std::string> fields;
    std::stringstream ss(text);
    for (std::string f; std::getline(ss, f, ',');) fields.push_back(f);
    if (!text.empty() && text.back() == ',') fields.push_back("");
    return fields;
  };
  const std::vector<std::string> columns = split(header);
  const auto column = [&](const std::string& name) {
    return std::find(columns.begin(), columns.end(), name) - columns.begin();
  };
  std::vector<std::string> last_fields;
  while (std::getline(in, line)) last_fields = split(line);
  ASSERT_EQ(last_fields.size(), columns.size());
  EXPECT_EQ(last_fields[column("floor_l2")], "1");  // level 6: L2 at the floor
  EXPECT_EQ(last_fields[column("floor_h1")], "0");
}

}  // namespace
}  // namespace iga
