// The C0 interior penalty form of the surface biharmonic (assembly/interior_penalty.hpp,
// SurfaceBiharmonicFormulation on C0 spaces): the interior edges of the RSD surface space, and the
// rates of a C0 space on a curved surface.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "tests/support/test_support.hpp"

namespace iga {
namespace {

/// The outward unit conormal of side `edge` of a triangle element at point q of `g`.
Eigen::Vector3d conormal(const PointValues& g, int q, int edge) {
  const Eigen::Matrix<double, 3, 2>& J = g.jacobian3[q];
  const Point2 t = reference_edge_tangent(CellShape::triangle, edge);
  const Eigen::Vector3d tangent = J * Eigen::Vector2d(t.x(), t.y());
  return tangent.cross(J.col(0).cross(J.col(1)).normalized()).normalized();
}

TEST(SurfaceC0ip, InteriorEdgesOfTheRsdSurfaceSpace) {
  // A closed surface of E triangle elements has 3E/2 interior edges; both sides of each meet at
  // the same points with opposite conormals (G1: one tangent plane), so the jumps of smooth
  // functions vanish there.
  const std::string yaml = "domain: {type: surface, mesh: icosphere, level: 1}\nspace: {type: surface, degree: 3}\n";
  for (int level = 0; level < 2; ++level) {
    const SpacePtr s = test::space_from_yaml(yaml, level);
    const std::vector<InteriorEdge> edges = s->interior_edges();
    EXPECT_EQ(2 * static_cast<int>(edges.size()), 3 * s->num_elements());  // 80 · 4^level elements
    auto evaluator = s->make_evaluator();
    double points = 0.0, conormals = 0.0;
    for (const InteriorEdge& e : edges) {
      QuadratureRule ra, rb;
      for (double t : {0.1, 0.5, 0.8}) {
        ra.points.push_back(reference_edge_point(CellShape::triangle, e.edge_a, e.a0 + t * (e.a1 - e.a0)));
        rb.points.push_back(reference_edge_point(CellShape::triangle, e.edge_b, e.b0 + t * (e.b1 - e.b0)));
      }
      ra.weights.assign(3, 0.0);
      rb.weights.assign(3, 0.0);
      PointValues a, b;
      evaluator->evaluate(e.element_a, ra, update_values | update_gradients, a);
      evaluator->evaluate(e.element_b, rb, update_values | update_gradients, b);
      for (int q = 0; q < 3; ++q) {
        points = std::max(points, (a.x3.col(q) - b.x3.col(q)).norm());
        conormals = std::max(conormals, (conormal(a, q, e.edge_a) + conormal(b, q, e.edge_b)).norm());
      }
    }
    EXPECT_LT(points, 1e-13);     // measured 8e-16
    EXPECT_LT(conormals, 1e-12);  // measured 2e-14 (the RSD surface's G1 residual)
  }
}

TEST(SurfaceC0ip, C0SpaceOnACurvedGraphConvergesAtItsRates) {
  // C0 cubic T-mesh splines (regularity 0) lifted onto z = x² − y², clamped (u, ∂_n u imposed by
  // the planar space), u = sin(2x + z) cos(y), penalty 4p²/h_E. C0-IP rates for degree p = 3:
  // broken H2 p − 1 = 2, H1 p = 3, L2 p + 1 = 4; levels 0–2 (measured 3.93 / 3.07 / 2.11).
  const test::Rates r = test::last_rates(
      "problem: {pde: surface_biharmonic, exact: \"sin(2*x + z)*cos(y)\", boundary: {all: clamped}}\n"
      "domain: {type: graph, height: \"x^2 - y^2\", over: {type: rectangle, min: [0, 0], max: [1, 1]}}\n"
      "space: {type: tmesh, section: poly, n: 3, regularity: 0, elements: [2, 2]}\n",
      3);
  EXPECT_NEAR(r.l2, 4.0, 0.3);
  EXPECT_NEAR(r.h1, 3.0, 0.3);
  EXPECT_NEAR(r.h2, 2.0, 0.3);
}

}  // namespace
}  // namespace iga
