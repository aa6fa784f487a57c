/// @file
/// Ws4Space::sample_cell draws on the split: cells tile the reference triangle, are
/// counterclockwise and each lies inside one polynomial piece (region) of the split.

#include <gtest/gtest.h>

#include "spaces/ws4/ws4_space.hpp"
#include "spaces/ws4/ws4_split.hpp"

namespace iga::ws4 {
namespace {

double signed_area(const SampleCell& s, const std::vector<int>& c) {
  const Point2 a = s.points[c[1]] - s.points[c[0]], b = s.points[c[2]] - s.points[c[0]];
  return 0.5 * (a.x() * b.y() - a.y() * b.x());
}

/// Cells are triangles of positive area summing to 1/2, each inside one region of the split.
void check_tiling(const SampleCell& s, int expected_points, int expected_cells) {
  const Ws4Split& split = Ws4Split::reference();
  ASSERT_EQ(static_cast<int>(s.points.size()), expected_points);
  ASSERT_EQ(static_cast<int>(s.cells.size()), expected_cells);
  double area = 0;
  for (const auto& c : s.cells) {
    ASSERT_EQ(c.size(), 3u);
    const double a = signed_area(s, c);
    EXPECT_GT(a, 0.0);
    area += a;
    // Points just inside the cell next to each corner fall in the same region as its centroid.
    const Point2 centroid = (s.points[c[0]] + s.points[c[1]] + s.points[c[2]]) / 3.0;
    const int region = split.locate(centroid);
    for (int v : c) EXPECT_EQ(split.locate(s.points[v] + 1e-6 * (centroid - s.points[v])), region);
  }
  EXPECT_NEAR(area, 0.5, 1e-13);
}

/// One reference triangle.
Ws4Space one_triangle() {
  return Ws4Space(Triangulation({{0, 0}, {1, 0}, {0, 1}}, {{0, 1, 2}}, {"boundary"}, [](int, int) { return 0; }));
}

TEST(Ws4SampleCell, SplitVerticesAndFanTriangles) { check_tiling(one_triangle().sample_cell(0, 8), 178, 342); }

TEST(Ws4SampleCell, SubdividedFanTriangles) {
  check_tiling(one_triangle().sample_cell(0, 16), 342 * 6, 342 * 4);
}

}  // namespace
}  // namespace iga::ws4
