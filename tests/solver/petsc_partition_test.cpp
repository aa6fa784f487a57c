// The element partition along a Hilbert curve and the distributed numbering of the unknowns.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <set>

#include "solver/petsc_partition.hpp"
#include "solver/petsc_session.hpp"

namespace iga {
namespace {

TEST(HilbertCurve, IsTheClassicalCurve) {
  // The 4 × 4 curve of the classical conversion (Wikipedia, "Hilbert curve", xy2d), row y = 3 on
  // top: the orientation fixes the partition and so PETSc's row order and GAMG's aggregates.
  const int expected[4][4] = {{5, 6, 9, 10}, {4, 7, 8, 11}, {3, 2, 13, 12}, {0, 1, 14, 15}};
  for (unsigned y = 0; y < 4; ++y)
    for (unsigned x = 0; x < 4; ++x) EXPECT_EQ(hilbert_index(x, y, 2), expected[3 - y][x]) << x << ", " << y;
  // At order 20 the first cell of each quadrant in the curve's order.
  constexpr unsigned half = 1u << 19, last = (1u << 20) - 1;
  EXPECT_EQ(hilbert_index(0, 0, 20), 0ULL);
  EXPECT_EQ(hilbert_index(0, half, 20), 1ULL << 38);
  EXPECT_EQ(hilbert_index(half, half, 20), 2ULL << 38);
  EXPECT_EQ(hilbert_index(last, half - 1, 20), 3ULL << 38);
  EXPECT_EQ(hilbert_index(last, 0, 20), (1ULL << 40) - 1);
}

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

TEST(ElementPartition, RunsOfTheOrderByKeyThenElementNumber) {
  // partition_by_keys finds the cuts by selection: the same runs as a stable sort of the keys cut
  // into equal lengths, with many equal keys (elements in one cell of the curve's grid).
  const int n = 1001;
  std::vector<unsigned long long> keys(n);
  unsigned long long state = 12345;
  for (auto& k : keys) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    k = (state >> 33) % 97;
  }
  std::vector<int> order(n);
  for (int e = 0; e < n; ++e) order[e] = e;
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return keys[a] < keys[b]; });
  for (int parts : {2, 3, 7, 1000, 1001, 1500}) {
    std::vector<int> expected(n);
    for (int k = 0; k < n; ++k) expected[order[k]] = static_cast<int>(static_cast<long long>(k) * parts / n);
    EXPECT_EQ(partition_by_keys(keys, parts), expected) << parts << " parts";
  }
}

}  // namespace
}  // namespace iga
