/// @file
/// The global WS4 space (WS4 notes §8, §12 "Gluing and FE"): dimension 10 n_V + 6 n_E + 3 n_T,
/// C³ across element edges for random coefficients on a perturbed mesh, exact reproduction of
/// quartics (values, gradients, Hessians), boundary parts and config errors.

#include "spaces/ws4/ws4_space.hpp"

#include <gtest/gtest.h>

#include <Eigen/LU>

#include <cmath>
#include <iostream>
#include <random>

#include "config/errors.hpp"
#include "spaces/element_values.hpp"
#include "spaces/ws4/ws4_basis.hpp"
#include "tests/spaces/ws4/ws4_test_meshes.hpp"
#include "tests/support/test_support.hpp"

namespace iga::ws4 {
namespace {

using test::perturbed_square;

/// A random quartic Σ c_ab x^a y^b and its derivatives of order <= 3 in the vertex-DOF order.
struct Quartic {
  double c[5][5] = {};
  explicit Quartic(unsigned seed) {
    std::mt19937 gen(seed);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int a = 0; a <= 4; ++a)
      for (int b = 0; a + b <= 4; ++b) c[a][b] = u(gen);
  }
  double d(const Point2& x, int i, int j) const {
    double s = 0.0;
    for (int a = i; a <= 4; ++a)
      for (int b = j; a + b <= 4; ++b) {
        double f = c[a][b];
        for (int k = 0; k < i; ++k) f *= a - k;
        for (int k = 0; k < j; ++k) f *= b - k;
        s += f * std::pow(x.x(), a - i) * std::pow(x.y(), b - j);
      }
    return s;
  }
  std::array<double, 10> jet(const Point2& x) const {
    return {d(x, 0, 0), d(x, 1, 0), d(x, 0, 1), d(x, 2, 0), d(x, 1, 1),
            d(x, 0, 2), d(x, 3, 0), d(x, 2, 1), d(x, 1, 2), d(x, 0, 3)};
  }
};

TEST(Ws4Space, DimensionOnTheUnitSquareMeshes) {
  const int expected[4] = {76, 210, 682, 2442};
  int k = 0;
  for (int n : {1, 2, 4, 8}) {
    const SpacePtr s = test::space_from_yaml("domain: {type: unit_square}\nspace: {type: ws4, elements: " +
                                             std::to_string(n) + "}\n");
    EXPECT_EQ(s->dimension(), expected[k++]) << n;
    EXPECT_EQ(s->num_elements(), 2 * n * n);
    EXPECT_EQ(s->type(), "ws4");
  }
  // One uniform 4-split of the 1 x 1 mesh has the counts of the 2 x 2 mesh.
  const SpacePtr refined =
      test::space_from_yaml("domain: {type: rectangle, min: [0, 0], max: [2, 1]}\nspace: {type: ws4, elements: 1}\n", 1);
  EXPECT_EQ(refined->dimension(), 210);
  EXPECT_NEAR(refined->mesh_size(), std::hypot(1.0, 0.5), 1e-15);
}

TEST(Ws4Space, BoundaryPartsAndConfigErrors) {
  const SpacePtr s = test::space_from_yaml("domain: {type: unit_square}\nspace: {type: ws4, elements: [3, 2]}\n");
  EXPECT_EQ(s->boundary_edges("bottom").size(), 3u);
  EXPECT_EQ(s->boundary_edges("left").size(), 2u);
  EXPECT_EQ(s->boundary_edges("all").size(), 10u);
  for (const BoundaryEdge& b : s->boundary_edges("top")) {
    // The edge lies on y = 1.
    ElementValues ev(*s, update_values);
    ev.reinit_edge(b.element, b.local_edge, *s->edge_quadrature(b.element, b.local_edge, 2));
    for (int q = 0; q < ev.num_points(); ++q) EXPECT_NEAR(ev.values().x(1, q), 1.0, 1e-15);
  }
  EXPECT_THROW(s->boundary_edges("north"), InputError);
  EXPECT_THROW(test::space_from_yaml("domain: {type: disk}\nspace: {type: ws4}\n"), InputError);
  EXPECT_THROW(test::space_from_yaml("domain: {type: unit_square}\nspace: {type: ws4, elements: 0}\n"), InputError);
  EXPECT_THROW(test::space_from_yaml("domain: {type: unit_square}\nspace: {type: ws4, degree: 3}\n"), InputError);
}

TEST(Ws4Space, C3AcrossElementEdgesOnAPerturbedMesh) {
  const Ws4Space space(perturbed_square(3, 17));
  const Triangulation& mesh = space.mesh();
  const Eigen::VectorXd coef = test::random_vector(space.dimension(), 5);

  // All partial derivatives of order <= 3 of the spline on element t at physical point x.
  auto derivatives = [&](int t, const Point2& x) {
    std::vector<int> dofs;
    space.element_dofs(t, dofs);
    Eigen::VectorXd local(dofs.size());
    for (size_t k = 0; k < dofs.size(); ++k) local(k) = coef(dofs[k]);
    const Eigen::VectorXd b = space.extraction(t) * local;  // coefficients of the B_i
    const Eigen::Matrix2d jinv = space.jacobian(t).inverse();
    const Point2 xi = jinv * (x - mesh.vertices()[mesh.triangle(t)[0]]);
    std::vector<double> out;
    double row[Ws4Basis::size];
    for (int order = 0; order <= 3; ++order)
      for (int j = 0; j <= order; ++j) {
        std::vector<Point2> dirs(order - j, Point2(jinv.col(0)));
        dirs.insert(dirs.end(), j, Point2(jinv.col(1)));
        Ws4Basis::reference().directional_derivatives(xi, dirs, row);
        out.push_back(Eigen::Map<const Eigen::VectorXd>(row, Ws4Basis::size).dot(b));
      }
    return out;
  };
  double max_jump = 0.0, max_value = 0.0;
  int interior = 0;
  for (int e = 0; e < mesh.num_edges(); ++e) {
    if (mesh.is_boundary_edge(e)) continue;
    ++interior;
    const Point2 xa = mesh.vertices()[mesh.edge(e)[0]], xb = mesh.vertices()[mesh.edge(e)[1]];
    for (double s : {0.0, 0.1, 0.25, 0.37, 0.5, 0.61, 0.75, 0.9, 1.0}) {
      const Point2 x = xa + s * (xb - xa);
      const std::vector<double> l = derivatives(mesh.edge_triangles(e)[0], x);
      const std::vector<double> r = derivatives(mesh.edge_triangles(e)[1], x);
      for (size_t k = 0; k < l.size(); ++k) {
        max_jump = std::max(max_jump, std::abs(l[k] - r[k]));
        max_value = std::max(max_value, std::abs(l[k]));
      }
    }
  }
  std::cout << interior << " interior edges: max jump of derivatives up to order 3 " << max_jump
            << ", max magnitude " << max_value << "\n";
  EXPECT_EQ(interior, 3 * 9 - 2 * 3);
  EXPECT_GT(max_value, 1e3);
  EXPECT_LT(max_jump, 1e-9 * max_value);
}

TEST(Ws4Space, ReproducesQuarticsExactlyOnAPerturbedMesh) {
  const Ws4Space space(perturbed_square(4, 23));
  const Quartic f(9);
  const Eigen::VectorXd coef = space.interpolate([&](const Point2& x) { return f.jet(x); });
  ElementValues ev(space, update_values | update_gradients | update_hessians);
  const RulePtr rule = space.quadrature(0, 4);
  double err[6] = {0, 0, 0, 0, 0, 0};
  for (int t = 0; t < space.num_elements(); ++t) {
    ev.reinit(t, *rule);
    const PointValues& pv = ev.values();
    Eigen::VectorXd local(pv.num_functions());
    for (int k = 0; k < pv.num_functions(); ++k) local(k) = coef(pv.dofs[k]);
    const Eigen::VectorXd v = pv.value.transpose() * local, dx = pv.dx.transpose() * local,
                          dy = pv.dy.transpose() * local, dxx = pv.dxx.transpose() * local,
                          dxy = pv.dxy.transpose() * local, dyy = pv.dyy.transpose() * local;
    for (int q = 0; q < pv.num_points(); ++q) {
      const Point2 x = pv.x.col(q);
      const double got[6] = {v(q), dx(q), dy(q), dxx(q), dxy(q), dyy(q)};
      const double exact[6] = {f.d(x, 0, 0), f.d(x, 1, 0), f.d(x, 0, 1), f.d(x, 2, 0), f.d(x, 1, 1), f.d(x, 0, 2)};
      for (int k = 0; k < 6; ++k) err[k] = std::max(err[k], std::abs(got[k] - exact[k]));
    }
  }
  std::cout << "quartic reproduction, max errors: value " << err[0] << ", gradient " << std::max(err[1], err[2])
            << ", Hessian " << std::max({err[3], err[4], err[5]}) << "\n";
  // Exact extraction (A⁻¹ exact, T_K in long double); quartic magnitudes O(1..10), h = 1/4. (The
  // former LU inverse of G_K gave 1e-12 / 5e-11 / 4e-9.)
  EXPECT_LT(err[0], 1e-13);
  EXPECT_LT(std::max(err[1], err[2]), 1e-11);
  EXPECT_LT(std::max({err[3], err[4], err[5]}), 1e-9);
}

TEST(Ws4Space, ShapeFunctionsAreDualToTheirDegreesOfFreedom) {
  const Ws4Space space(perturbed_square(2, 3));
  for (int t = 0; t < space.num_elements(); ++t) {
    const Eigen::MatrixXd id = space.element_functionals(t) * space.extraction(t);
    EXPECT_LT((id - Eigen::MatrixXd::Identity(51, 51)).cwiseAbs().maxCoeff(), 1e-9) << t;
  }
}

}  // namespace
}  // namespace iga::ws4
