// The element partition along a Hilbert curve and the distributed numbering of the unknowns.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <set>

#include "solver/petsc_partition.hpp"
#include "solver/petsc_session.hpp"

namespace iga {
namespace {

TEST(HilbertCurve, VisitsEveryCellOnceMovingToANeighbourEachStep) {
  constexpr int order = 4, n = 1 << order;
  std::vector<std::pair<int, int>> cell_at(n * n, {-1, -1});
  for (int x = 0; x < n; ++x)
    for (int y = 0; y < n; ++y) {
      const auto d = hilbert_index(x, y, order);
      ASSERT_LT(d, static_cast<unsigned long long>(n * n));
      ASSERT_EQ(cell_at[d].first, -1) << "index " << d << " twice";
      cell_at[d] = {x, y};
    }
  for (int d = 1; d < n * n; ++d)
    EXPECT_EQ(std::abs(cell_at[d].first - cell_at[d - 1].first) + std::abs(cell_at[d].second - cell_at[d - 1].second), 1);
}

/// Centres of an m × m grid of unit squares.
std::vector<Point2> grid_centres(int m) {
  std::vector<Point2> c;
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) c.emplace_back(i + 0.5, j + 0.5);
  return c;
}

TEST(ElementPartition, BalancedAndCompact) {
  const int m = 32, parts = 4;
  const std::vector<Point2> centres = grid_centres(m);
  const std::vector<int> owner = partition_elements(centres, parts);
  std::vector<int> size(parts, 0);
  for (int o : owner) ++size[o];
  for (int s : size) EXPECT_EQ(s, m * m / parts);
  // A Hilbert curve cut into 4 equal runs gives the 4 quadrants: the cut is the two mid-lines.
  int cut = 0;
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) {
      if (i + 1 < m) cut += owner[j * m + i] != owner[j * m + i + 1];
      if (j + 1 < m) cut += owner[j * m + i] != owner[(j + 1) * m + i];
    }
  EXPECT_EQ(cut, 2 * m);
  EXPECT_EQ(partition_elements(centres, 1), std::vector<int>(m * m, 0));
}

TEST(UnknownLayout, LowestOwningRankAndContiguousRows) {
  // Three elements in a row sharing one unknown each: 0 {0,1}, 1 {1,2}, 2 {2,3}; owners 1, 0, 1.
  const std::vector<int> offsets{0, 2, 4, 6}, unknowns{0, 1, 1, 2, 2, 3}, owner{1, 0, 1};
  const UnknownLayout layout = layout_unknowns(offsets, unknowns, owner, 4, 2);
  EXPECT_EQ(layout.owner, (std::vector<int>{1, 0, 0, 1}));
  EXPECT_EQ(layout.first_row, (std::vector<int>{0, 2, 4}));
  EXPECT_EQ(layout.global, (std::vector<int>{2, 0, 1, 3}));
}

TEST(RowCouplings, CountsColumnsOnAndOffTheRankOncePerRow) {
  // The chain above: rank 0 owns unknowns 1, 2 (rows 0, 1), rank 1 owns 0, 3 (rows 2, 3).
  const std::vector<int> offsets{0, 2, 4, 6}, unknowns{0, 1, 1, 2, 2, 3}, owner{1, 0, 1};
  const UnknownLayout layout = layout_unknowns(offsets, unknowns, owner, 4, 2);
  // Unknown 1 couples 0, 1, 2; unknown 2 couples 1, 2, 3. In rows: 0 and 1 are rank 0's.
  const RowCouplings zero = row_couplings(offsets, unknowns, layout, 0);
  EXPECT_EQ(zero.on_rank_columns, (std::vector<int>{2, 2}));
  EXPECT_EQ(zero.off_rank_columns, (std::vector<int>{1, 1}));
  EXPECT_EQ(zero.off_rank, 2);
  EXPECT_EQ(zero.total, 6);
  // Unknown 0 couples 0, 1; unknown 3 couples 2, 3: one column on rank 1, one off, each.
  const RowCouplings one = row_couplings(offsets, unknowns, layout, 1);
  EXPECT_EQ(one.on_rank_columns, (std::vector<int>{1, 1}));
  EXPECT_EQ(one.off_rank_columns, (std::vector<int>{1, 1}));
}

TEST(PetscArguments, PetscOptionsAndTheirValuesAreSplitOff) {
  const auto [own, petsc] = split_petsc_arguments(
      {"iga-run", "-ksp_monitor", "c.yaml", "-o", "out", "-ksp_rtol", "1e-10", "-l", "2", "-pc_gamg_threshold",
       "-0.5", "-log_view", "-q", "-info"});
  EXPECT_EQ(own, (std::vector<std::string>{"iga-run", "c.yaml", "-o", "out", "-l", "2", "-q"}));
  EXPECT_EQ(petsc, (std::vector<std::string>{"iga-run", "-ksp_monitor", "-ksp_rtol", "1e-10", "-pc_gamg_threshold",
                                             "-0.5", "-log_view", "-info"}));
}

}  // namespace
}  // namespace iga
