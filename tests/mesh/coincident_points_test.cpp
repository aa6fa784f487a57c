// Coincident points by a hash grid: a strip with every point on two vertical lines (the case that
// made a sort on x quadratic) is checked in well under a second at 300000 points, and a real pair
// in it is found; the two closeness rules and the pair's order.

#include "mesh/coincident_points.hpp"

#include <gtest/gtest.h>

#include <ctime>
#include <cmath>
#include <numeric>

#include "mesh/planar_mesh.hpp"
#include "mesh/validate_planar_mesh.hpp"

namespace iga {
namespace {

std::vector<int> all_ids(std::size_t n) {
  std::vector<int> ids(n);
  std::iota(ids.begin(), ids.end(), 0);
  return ids;
}

/// Points (0, k h) and (1, k h), alternating, as the rows of a one-cell-wide strip.
std::vector<Eigen::Vector2d> strip(int n) {
  std::vector<Eigen::Vector2d> p;
  const double h = 1.0 / (n / 2);
  for (int k = 0; k < n / 2; ++k) p.emplace_back(0.0, k * h), p.emplace_back(1.0, k * h);
  return p;
}

// Not a speed test: a quadratic search over these 300000 points costs tens of seconds (4.5e10 pairs), the
// hash grid a fraction of a second. The bound separates the two by a wide margin on either side,
// and it is process CPU time, which a loaded machine does not inflate as it does wall time (two
// tests failed at a 1 s wall-time bound under a load of 9 on 2 cores).
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
constexpr double time_limit = 30.0;  // instrumented builds run several times slower
#else
constexpr double time_limit = 5.0;
#endif

/// CPU seconds of this process since `start` (std::clock).
double cpu_seconds_since(std::clock_t start) { return static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC; }

TEST(CoincidentPoints, AStripOnTwoLinesIsLinear) {
  const std::vector<Eigen::Vector2d> p = strip(300000);
  const double eps = mesh_tolerance * std::sqrt(2.0);
  const std::clock_t start = std::clock();
  EXPECT_FALSE(find_coincident_points(p, all_ids(p.size()), eps, Closeness::every_coordinate));
  EXPECT_LT(cpu_seconds_since(start), time_limit);

  std::vector<Eigen::Vector2d> q = p;
  q[200001] = q[70001] + Eigen::Vector2d(0.5 * eps, -0.5 * eps);  // on x = 1, beside another row
  const auto pair = find_coincident_points(q, all_ids(q.size()), eps, Closeness::every_coordinate);
  ASSERT_TRUE(pair);
  EXPECT_EQ(*pair, std::make_pair(70001, 200001));
}

TEST(CoincidentPoints, AStripThroughThePlanarMeshCheck) {
  PlanarMesh m;
  m.source = "strip.off";
  m.vertices = strip(300000);
  for (int k = 0; k + 1 < 150000; ++k) m.cells.push_back({2 * k, 2 * k + 1, 2 * k + 3, 2 * k + 2});
  m.vertices.push_back(m.vertices[4]);  // the third row's left corner, twice: cells 1 and 2 not joined
  m.cells[2][0] = 300000;
  const std::clock_t start = std::clock();
  try {
    validate_planar_mesh(m);
    ADD_FAILURE() << "no error";
  } catch (const std::exception& e) {
    EXPECT_EQ(std::string(e.what()).rfind("strip.off: vertex 4 (0, ", 0), 0u) << e.what();
    EXPECT_NE(std::string(e.what()).find(" and vertex 300000 coincide"), std::string::npos) << e.what();
  }
  EXPECT_LT(cpu_seconds_since(start), time_limit);
}

TEST(CoincidentPoints, EachCoordinateOrDistance) {
  const std::vector<Eigen::Vector3d> p = {{0, 0, 0}, {5, 5, 5}, {0.8, 0.8, 0}, {5, 5, 5.9}};
  // Each coordinate within 1: points 0 and 2, before 1 and 3 (the later of a pair decides).
  EXPECT_EQ(find_coincident_points(p, all_ids(4), 1.0, Closeness::every_coordinate), std::make_pair(0, 2));
  // Euclidean: 0 and 2 are 1.13 apart; 1 and 3 0.9.
  EXPECT_EQ(find_coincident_points(p, all_ids(4), 1.0, Closeness::distance), std::make_pair(1, 3));
  // Only the ids given take part, in their order.
  EXPECT_EQ(find_coincident_points(p, std::vector<int>{3, 2, 1}, 1.0, Closeness::distance), std::make_pair(3, 1));
  EXPECT_FALSE(find_coincident_points(p, std::vector<int>{0, 1}, 1.0, Closeness::distance));
  // A tolerance of zero finds exact copies only; a point that is not finite meets no other.
  const std::vector<Eigen::Vector3d> q = {{1, 2, 3}, {NAN, 2, 3}, {1, 2, 3.000001}, {1, 2, 3}, {NAN, 2, 3}};
  EXPECT_EQ(find_coincident_points(q, all_ids(5), 0.0, Closeness::distance), std::make_pair(0, 3));
}

}  // namespace
}  // namespace iga
