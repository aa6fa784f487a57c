/// @file
/// The WS4 split of the reference triangle against the exact counts of the WS4 notes (§1.3, §12):
/// 39 lines, 178 vertices, 429 segments, 252 convex regions, 342 fan triangles.

#include "spaces/ws4/ws4_split.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace iga::ws4 {
namespace {

const Ws4Split& split() { return Ws4Split::reference(); }

TEST(Ws4Split, LinesAreThreeEdgesAndThirtySixCrossCuts) {
  ASSERT_EQ(split().lines().size(), 39u);
  // A few cross-cuts from the table of §1.2 (c . lambda = 0).
  for (Triple l : {Triple{1, -3, 9}, Triple{9, -3, 1}, Triple{1, 9, -3}, Triple{3, 3, -1}, Triple{1, -1, 0}})
    EXPECT_NE(std::find(split().lines().begin(), split().lines().end(), l), split().lines().end())
        << l[0] << " " << l[1] << " " << l[2];
}

TEST(Ws4Split, VertexCountsAndLineMultiplicities) {
  ASSERT_EQ(split().vertices().size(), 178u);
  int boundary = 0, by_lines[6] = {0, 0, 0, 0, 0, 0};
  for (size_t v = 0; v < split().vertices().size(); ++v) {
    const Triple& b = split().vertices()[v];
    const int k = split().lines_through_vertex()[v];
    if (b[0] == 0 || b[1] == 0 || b[2] == 0) {
      ++boundary;
      // p_k lie on 5 lines, the 9 quarter/mid points on 8.
      EXPECT_TRUE(k == 5 || k == 8) << k;
    } else {
      ASSERT_LE(k, 5);
      ++by_lines[k];
    }
  }
  EXPECT_EQ(boundary, 12);
  EXPECT_EQ(by_lines[2], 123);
  EXPECT_EQ(by_lines[3], 37);
  EXPECT_EQ(by_lines[4], 6);
  // The interior Hermite point v3 = (3/8, 3/8, 1/4) is a 4-line vertex.
  const auto it = std::find(split().vertices().begin(), split().vertices().end(), Triple{3, 3, 2});
  ASSERT_NE(it, split().vertices().end());
  EXPECT_EQ(split().lines_through_vertex()[it - split().vertices().begin()], 4);
}

TEST(Ws4Split, RegionsTrianglesQuadrilateralsAndAreas) {
  EXPECT_EQ(split().segments().size(), 429u);
  ASSERT_EQ(split().regions().size(), 252u);
  int tri = 0, quad = 0;
  double total = 0.0, smallest = 1.0, largest = 0.0;
  for (const SplitRegion& r : split().regions()) {
    tri += r.vertices.size() == 3;
    quad += r.vertices.size() == 4;
    total += r.area;
    smallest = std::min(smallest, r.area);
    largest = std::max(largest, r.area);
  }
  EXPECT_EQ(tri, 162);
  EXPECT_EQ(quad, 90);
  EXPECT_NEAR(total, 0.5, 1e-15);
  EXPECT_NEAR(smallest, 0.5 / 4480, 1e-17);
  EXPECT_NEAR(largest, 0.5 / 64, 1e-17);
  EXPECT_EQ(split().fan_triangles().size(), 342u);
}

TEST(Ws4Split, LocateFindsTheRegionOfItsCentroidAndOfRandomPoints) {
  for (int r = 0; r < static_cast<int>(split().regions().size()); ++r)
    ASSERT_EQ(split().locate(split().regions()[r].centroid), r);
  // Random points: the located region's polygon contains the point.
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int k = 0; k < 2000; ++k) {
    Point2 x(u(gen), u(gen));
    if (x.sum() > 1.0) x = Point2(1.0 - x.x(), 1.0 - x.y());
    const SplitRegion& reg = split().regions()[split().locate(x)];
    for (size_t i = 0; i < reg.vertices.size(); ++i) {
      const Point2 a = split().vertex_point(reg.vertices[i]);
      const Point2 b = split().vertex_point(reg.vertices[(i + 1) % reg.vertices.size()]);
      const Point2 e = b - a, d = x - a;
      ASSERT_GE(e.x() * d.y() - e.y() * d.x(), -1e-14);
    }
  }
  // Boundary points get a region inside the triangle (one-sided rule), also slightly outside.
  EXPECT_GE(split().locate(Point2(0.0, 0.0)), 0);
  EXPECT_GE(split().locate(Point2(0.25, -1e-17)), 0);
  EXPECT_THROW(split().locate(Point2(0.5, -0.5)), std::invalid_argument);
}

TEST(Ws4Split, CompositeRuleIntegratesPiecewisePolynomialsSubRegionBySubRegion) {
  const QuadratureRule rule = split().composite_rule(4);
  EXPECT_EQ(rule.size() % 342, 0);
  double area = 0.0, x4 = 0.0, kink = 0.0;
  for (int q = 0; q < rule.size(); ++q) {
    const Point2& p = rule.points[q];
    area += rule.weights[q];
    x4 += rule.weights[q] * std::pow(p.x(), 4);
    // |x - y|^3 has a kink on the split line x = y (p1-q1): exact only region by region.
    kink += rule.weights[q] * std::pow(std::abs(p.x() - p.y()), 3);
  }
  EXPECT_NEAR(area, 0.5, 1e-13);
  EXPECT_NEAR(x4, 1.0 / 30, 1e-14);  // 4! 0! / 6!
  // ∫_T |x-y|^3 = 2 ∫_{x>y} (x-y)^3 = 2 * 1/2 ∫_0^1 s^3 (1 - s) ds = 1/20 (s = x-y, t = x+y).
  EXPECT_NEAR(kink, 1.0 / 20, 1e-14);
}

}  // namespace
}  // namespace iga::ws4
