/// @file
/// WS4 essential boundary conditions through the generic boundary projection on a domain with
/// slanted boundary edges (boundary-adapted vertex frames, ws4_space.hpp): the constrained counts of
/// the WS4 notes §8.7, exact reproduction of quartic data, and optimal rates for Poisson and the
/// clamped plate with inhomogeneous data.

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "assembly/boundary_conditions.hpp"
#include "solver/solve_problem.hpp"
#include "spaces/ws4/ws4_space.hpp"
#include "tests/support/test_support.hpp"

namespace iga::ws4 {
namespace {

/// The quadrilateral (0,0), (1,0.2), (1.3,1), (0.2,0.9) as 2 triangles, refined `level` times:
/// 4 corners, every boundary edge slanted.
Ws4Space quadrilateral(int level) {
  Triangulation mesh({{0, 0}, {1, 0.2}, {1.3, 1}, {0.2, 0.9}}, {{0, 1, 2}, {0, 2, 3}}, {"boundary"},
                     [](int, int) { return 0; });
  for (int l = 0; l < level; ++l) mesh = mesh.refined();
  return Ws4Space(std::move(mesh));
}

TEST(Ws4Boundary, ConstrainedCountsOnSlantedEdges) {
  const Ws4Space space = quadrilateral(1);  // 8 boundary edges, 4 corners, 4 straight boundary vertices
  EssentialBoundary b;
  b.value_edges = space.boundary_edges("all");
  const BoundaryField zero = [](const Point2&, const Point2&) { return 0.0; };
  const Constraints dirichlet = impose_essential(space, b, zero, zero, 12);
  EXPECT_EQ(dirichlet.constrained.size(), 4u * 7 + 4 * 4);
  b.normal_edges = b.value_edges;
  const Constraints clamped = impose_essential(space, b, zero, zero, 12);
  EXPECT_EQ(clamped.constrained.size(), 4u * 10 + 4 * 7 + 8);
}

TEST(Ws4Boundary, QuarticDataAreMatchedExactly) {
  const Ws4Space space = quadrilateral(1);
  // u = (x - 2y)^4 + x^3 y: the projection of its boundary data reproduces its Hermite DOFs.
  auto u = [](const Point2& p) { return std::pow(p.x() - 2 * p.y(), 4) + p.x() * p.x() * p.x() * p.y(); };
  auto grad = [](const Point2& p) {
    const double s = 4 * std::pow(p.x() - 2 * p.y(), 3);
    return Point2(s + 3 * p.x() * p.x() * p.y(), -2 * s + p.x() * p.x() * p.x());
  };
  const Eigen::VectorXd exact = space.interpolate([&](const Point2& p) {
    const double x = p.x(), y = p.y(), s = x - 2 * y;
    return std::array<double, 10>{u(p),
                                  grad(p).x(),
                                  grad(p).y(),
                                  12 * s * s + 6 * x * y,
                                  -24 * s * s + 3 * x * x,
                                  48 * s * s,
                                  24 * s + 6 * y,
                                  -48 * s + 6 * x,
                                  96 * s,
                                  -192 * s};
  });
  EssentialBoundary b;
  b.value_edges = space.boundary_edges("all");
  b.normal_edges = b.value_edges;
  const Constraints c = impose_essential(
      space, b, [&](const Point2& x, const Point2&) { return u(x); },
      [&](const Point2& x, const Point2& n) { return grad(x).dot(n); }, 12);
  double err = 0.0, scale = 0.0;
  for (int i : c.constrained) {
    err = std::max(err, std::abs(c.values(i) - exact(i)));
    scale = std::max(scale, std::abs(exact(i)));
  }
  EXPECT_LT(err, 1e-10 * scale);
}

TEST(Ws4Boundary, OptimalRatesOnTheSlantedQuadrilateral) {
  for (const char* yaml : {R"yaml(
problem: {pde: poisson, exact: "sin(2*x+y)*exp(x*y/2)", boundary: {all: dirichlet}}
)yaml",
                           R"yaml(
problem: {pde: biharmonic, exact: "sin(2*x+y)*exp(x*y/2)", boundary: {all: clamped}}
)yaml"}) {
    const ProblemSpec problem = test::problem_from_yaml(yaml);
    std::vector<LevelResult> rows;
    for (int level = 1; level <= 2; ++level)
      rows.push_back(solve_problem(quadrilateral(level), problem, SolverKind::cholmod).result);
    const LevelResult &a = rows[0], &b = rows[1];
    const double r0 = *rate(a.l2, b.l2, a.h, b.h), r1 = *rate(a.h1, b.h1, a.h, b.h), r2 = *rate(a.h2, b.h2, a.h, b.h);
    std::cout << "slanted quadrilateral, " << (problem.pde == Pde::poisson ? "poisson" : "clamped plate") << ": L2 " << *b.l2 << " H1 " << *b.h1 << " H2 "
              << *b.h2 << ", rates " << r0 << " / " << r1 << " / " << r2 << "\n";
    EXPECT_GE(r0, 4.6);
    EXPECT_GE(r1, 3.6);
    EXPECT_GE(r2, 2.6);
  }
}

}  // namespace
}  // namespace iga::ws4
