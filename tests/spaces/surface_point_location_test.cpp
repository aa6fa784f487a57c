// Points of surfaces (spaces/surface_point_location.hpp): a point on the surface is located exactly,
// and a point off it at distance δ along the normal snaps to its foot (nearest_on_surface), which
// locate_on_surface refuses at a tolerance below δ.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "spaces/surface_point_location.hpp"
#include "tests/support/test_support.hpp"

namespace iga {
namespace {

TEST(SurfacePointLocation, PointsOffTheSurfaceSnapToTheirFoot) {
  // The exact NURBS torus (R = 2, r = 1): the foot of a point p = x + δ n is x itself when δ is
  // below the distance to the other side (r = 1). Checked at interior points of three elements.
  const SpacePtr space = test::space_from_yaml(
      "domain: {type: surface_patch, shape: torus, major_radius: 2, minor_radius: 1}\n"
      "space: {type: bspline, degree: 3, elements: [8, 4]}\n");
  const auto evaluator = space->make_evaluator();
  for (const int e : {0, 13, 30}) {
    QuadratureRule one;
    one.points = {Point2(0.3, 0.7)};
    one.weights = {0.0};
    PointValues g;
    evaluator->evaluate_geometry(e, one, g);
    const Eigen::Vector3d x = g.x3.col(0);
    const Eigen::Vector3d n = Eigen::Vector3d(g.jacobian3[0].col(0)).cross(Eigen::Vector3d(g.jacobian3[0].col(1))).normalized();
    const auto on = locate_on_surface(*space, x, *evaluator, 1e-10);
    ASSERT_TRUE(on.has_value()) << e;
    for (const double delta : {1e-4, 0.1}) {
      const Eigen::Vector3d p = x + delta * n;
      EXPECT_FALSE(locate_on_surface(*space, p, *evaluator, 0.5 * delta).has_value()) << e << " " << delta;
      double distance = 0;
      const auto at = nearest_on_surface(*space, p, *evaluator, distance);
      ASSERT_TRUE(at.has_value());
      one.points = {at->reference};
      evaluator->evaluate_geometry(at->element, one, g);
      // Newton stops at 1e-14 in the reference cell: the foot to rounding of the map's size.
      EXPECT_NEAR(distance, delta, 1e-12) << e << " " << delta;
      EXPECT_LT((g.x3.col(0) - x).norm(), 1e-10) << e << " " << delta;
    }
  }
}

}  // namespace
}  // namespace iga
