/// @file
/// jitter_interior_vertices and the `jitter` domain key: boundary vertices stay, interior vertices
/// move by at most the bound, the pattern is reproducible per seed, no triangle flips.

#include "spaces/ws4/ws4_jitter.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "config/config_node.hpp"
#include "config/errors.hpp"
#include "spaces/ws4/ws4_from_config.hpp"
#include "spaces/ws4/ws4_space.hpp"

namespace iga::ws4 {
namespace {

double signed_area(const Triangulation& m, int t) {
  const auto& v = m.triangle(t);
  const Point2 a = m.vertices()[v[1]] - m.vertices()[v[0]], b = m.vertices()[v[2]] - m.vertices()[v[0]];
  return 0.5 * (a.x() * b.y() - a.y() * b.x());
}

TEST(Ws4Jitter, MovesOnlyInteriorVerticesWithinBound) {
  const Triangulation regular = Triangulation::rectangle(4, 4, Point2(0, 0), Point2(1, 1));
  Triangulation moved = regular;
  jitter_interior_vertices(moved, 0.2, 5);
  int interior = 0;
  double largest = 0;
  for (int v = 0; v < regular.num_vertices(); ++v) {
    const Point2 x = regular.vertices()[v];
    const double d = (moved.vertices()[v] - x).cwiseAbs().maxCoeff();
    const bool boundary = x.x() == 0 || x.x() == 1 || x.y() == 0 || x.y() == 1;
    if (boundary) {
      EXPECT_EQ(d, 0.0) << "vertex " << v;
    } else {
      ++interior;
      EXPECT_LE(d, 0.2 * 0.25 + 1e-15);  // shortest edge at an interior vertex: 1/4
      largest = std::max(largest, d);
    }
  }
  EXPECT_EQ(interior, 9);
  EXPECT_GT(largest, 0.01);
  for (int t = 0; t < moved.num_triangles(); ++t)
    EXPECT_GT(signed_area(moved, t), 0.3 * signed_area(regular, t)) << "triangle " << t;
}

TEST(Ws4Jitter, ReproduciblePerSeed) {
  Triangulation a = Triangulation::rectangle(3, 3, Point2(0, 0), Point2(1, 1)), b = a, c = a;
  jitter_interior_vertices(a, 0.1, 7);
  jitter_interior_vertices(b, 0.1, 7);
  jitter_interior_vertices(c, 0.1, 8);
  double ab = 0, ac = 0;
  for (int v = 0; v < a.num_vertices(); ++v) {
    ab = std::max(ab, (a.vertices()[v] - b.vertices()[v]).norm());
    ac = std::max(ac, (a.vertices()[v] - c.vertices()[v]).norm());
  }
  EXPECT_EQ(ab, 0.0);
  EXPECT_GT(ac, 1e-3);
}

TEST(Ws4Jitter, ConfigKey) {
  const ConfigNode root = ConfigNode::load_string(
      "domain: {type: unit_square, jitter: 0.15, seed: 3}\nspace: {type: ws4, elements: 2}\n", "t.yaml");
  const SpacePtr s = make_ws4_space(root["domain"], root["space"], 1);
  const auto& ws4 = dynamic_cast<const Ws4Space&>(*s);
  const Triangulation regular = Triangulation::rectangle(2, 2, Point2(0, 0), Point2(1, 1)).refined();
  double moved = 0;
  for (int v = 0; v < regular.num_vertices(); ++v)
    moved = std::max(moved, (ws4.mesh().vertices()[v] - regular.vertices()[v]).norm());
  EXPECT_GT(moved, 1e-3);
  EXPECT_LT(moved, 0.15 * 0.25 * std::sqrt(2.0) + 1e-12);
  const ConfigNode bad = ConfigNode::load_string(
      "domain: {type: unit_square, jitter: 0.5}\nspace: {type: ws4, elements: 2}\n", "t.yaml");
  EXPECT_THROW(make_ws4_space(bad["domain"], bad["space"], 0), InputError);
}

}  // namespace
}  // namespace iga::ws4
