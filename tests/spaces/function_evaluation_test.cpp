/// @file
/// Space::Evaluator::evaluate_function and integrate_values: the WS4, T-mesh, B-spline, G1 and
/// 4-split fast paths (contract with the extraction first) agree with the plain path (all active
/// functions from evaluate, then contract) to round-off, on a perturbed WS4 mesh, a graded T-mesh, a
/// curved B-spline patch and G1 multipatch meshes; Assembler::load agrees with the
/// element-by-element load from ElementValues.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

#include "assembly/assembler.hpp"
#include "config/config_node.hpp"
#include "spaces/bspline/bspline_from_config.hpp"
#include "spaces/element_values.hpp"
#include "spaces/space_factory.hpp"
#include "spaces/ws4/ws4_space.hpp"
#include "tests/support/test_support.hpp"

namespace iga {
namespace {

SpacePtr perturbed_ws4(int n) {
  ws4::Triangulation mesh = ws4::Triangulation::rectangle(n, n, Point2(0, 0), Point2(1, 1));
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> u(-0.15 / n, 0.15 / n);
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    const Point2 x = mesh.vertices()[v];
    if (x.x() > 0 && x.x() < 1 && x.y() > 0 && x.y() < 1) mesh.move_vertex(v, x + Point2(u(gen), u(gen)));
  }
  return std::make_shared<const ws4::Ws4Space>(std::move(mesh));
}

SpacePtr annulus_bspline() {
  const ConfigNode root = ConfigNode::load_string(
      "domain: {type: quarter_annulus, inner: 1, outer: 2}\n"
      "space: {type: bspline, degree: 3, regularity: 2, elements: [3, 2]}\n",
      "test.yaml");
  return make_bspline_space(root["domain"], root["space"], 0);
}

/// A C1 trigonometric T-mesh with cells of three sizes (hanging vertices).
SpacePtr graded_tmesh() {
  const ConfigNode root = ConfigNode::load_string(
      "domain: {type: rectangle, min: [0, 0], max: [2, 1.5]}\n"
      "space: {type: tmesh, section: trig, n: 3, regularity: 1, elements: [4, 4],\n"
      "        refine: [[0, 0, 0.5, 0.5], [0.25, 0.25, 0.5, 0.5]]}\n",
      "test.yaml");
  return make_space(root["domain"], root["space"], 1);
}

/// G1 multipatch splines (k = 5, three quadrilateral patches) and the 4-split G1 macro-patches.
SpacePtr g1_three_patches() { return test::space_from_yaml("domain: {type: multipatch, name: 3p_square}\nspace: {type: g1, degree: 5}\n", 1); }
SpacePtr g1_4split_fan() {
  return test::space_from_yaml("domain: {type: multipatch, name: fan3}\nspace: {type: g1_4split, degree: 5}\n", 0);
}

using test::random_vector;

double max_abs_diff(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  EXPECT_EQ(a.size(), b.size());
  return (a - b).cwiseAbs().maxCoeff();
}

/// evaluate_function and the contraction of every active function from evaluate agree on every
/// element; values are compared relative to the largest magnitude of each quantity.
void check_function_paths(const Space& space, int quad_degree) {
  const Eigen::VectorXd c = random_vector(space.dimension(), 11);
  const unsigned flags = update_values | update_gradients | update_hessians;
  auto evaluator = space.make_evaluator();
  PointValues g_fast, g_default;
  FunctionValues fast, slow;
  double scale[6] = {}, diff[6] = {};
  for (int e = 0; e < space.num_elements(); ++e) {
    const RulePtr rule_ptr = space.quadrature(e, quad_degree);  // keeps the rule alive
    const QuadratureRule& rule = *rule_ptr;
    evaluator->evaluate_function(e, rule, c, flags, g_fast, fast);
    evaluator->evaluate(e, rule, flags, g_default);
    Eigen::VectorXd active(g_default.num_functions());
    for (int i = 0; i < active.size(); ++i) active(i) = c(g_default.dofs[i]);
    slow.value = g_default.value.transpose() * active;
    slow.dx = g_default.dx.transpose() * active;
    slow.dy = g_default.dy.transpose() * active;
    slow.dxx = g_default.dxx.transpose() * active;
    slow.dxy = g_default.dxy.transpose() * active;
    slow.dyy = g_default.dyy.transpose() * active;
    ASSERT_EQ(g_fast.dofs, g_default.dofs);
    ASSERT_EQ(fast.value.size(), rule.size());
    EXPECT_LT((g_fast.x - g_default.x).cwiseAbs().maxCoeff(), 1e-15);
    const Eigen::VectorXd* f[6] = {&fast.value, &fast.dx, &fast.dy, &fast.dxx, &fast.dxy, &fast.dyy};
    const Eigen::VectorXd* s[6] = {&slow.value, &slow.dx, &slow.dy, &slow.dxx, &slow.dxy, &slow.dyy};
    for (int a = 0; a < 6; ++a) {
      scale[a] = std::max(scale[a], s[a]->cwiseAbs().maxCoeff());
      diff[a] = std::max(diff[a], max_abs_diff(*f[a], *s[a]));
    }
  }
  for (int a = 0; a < 6; ++a) {
    EXPECT_GT(scale[a], 1e-3) << "quantity " << a;
    EXPECT_LT(diff[a], 1e-11 * scale[a]) << "quantity " << a;
  }
}

/// Fast and default integrate_values agree, and both equal value-table times weights.
void check_integrate_paths(const Space& space, int quad_degree) {
  auto evaluator = space.make_evaluator();
  ElementValues ev(space, update_values);
  PointValues geometry;
  Eigen::VectorXd fast, slow;
  double scale = 0, diff = 0;
  for (int e = 0; e < space.num_elements(); ++e) {
    const RulePtr rule_ptr = space.quadrature(e, quad_degree);  // keeps the rule alive
    const QuadratureRule& rule = *rule_ptr;
    const Eigen::VectorXd g = random_vector(rule.size(), 100 + e);
    evaluator->evaluate_geometry(e, rule, geometry);
    evaluator->integrate_values(e, rule, geometry, g, fast);
    ev.reinit(e, rule);
    slow = ev.values().value * g;
    ASSERT_EQ(geometry.dofs, ev.dofs());
    scale = std::max(scale, slow.cwiseAbs().maxCoeff());
    diff = std::max(diff, max_abs_diff(fast, slow));
  }
  EXPECT_GT(scale, 1e-3);
  EXPECT_LT(diff, 1e-11 * scale);
}

/// Assembler::load against the load built element by element from ElementValues.
void check_load(const Space& space, int quad_degree) {
  const ScalarField f = [](const Point2& x) { return std::sin(2 * x.x()) * std::exp(x.y()) + 0.5; };
  const Eigen::VectorXd fast = Assembler(space).load(f, quad_degree);
  Eigen::VectorXd slow = Eigen::VectorXd::Zero(space.dimension());
  ElementValues ev(space, update_values);
  Eigen::VectorXd local;
  for (int e = 0; e < space.num_elements(); ++e) {
    ev.reinit(e, *space.quadrature(e, quad_degree));
    // ∫ f N_i by the point values of every function (the route the fast load avoids).
    Eigen::VectorXd fw(ev.num_points());
    for (int k = 0; k < ev.num_points(); ++k) fw(k) = f(ev.values().x.col(k)) * ev.jxw()(k);
    local.noalias() = ev.values().value * fw;
    for (int i = 0; i < local.size(); ++i) slow(ev.dofs()[i]) += local(i);
  }
  const double scale = slow.cwiseAbs().maxCoeff();
  EXPECT_GT(scale, 1e-4);
  EXPECT_LT(max_abs_diff(fast, slow), 1e-12 * scale);
}

/// The WS4 fast path reproduces a quartic from its Hermite interpolant (values to Hessians).
TEST(FunctionEvaluation, Ws4FastPathReproducesQuartic) {
  const SpacePtr space = perturbed_ws4(3);
  const auto& ws4 = dynamic_cast<const ws4::Ws4Space&>(*space);
  // f = x^4 + x y^3 + y^2 and its derivatives in the vertex-DOF order.
  const Eigen::VectorXd c = ws4.interpolate([](const Point2& p) {
    const double x = p.x(), y = p.y();
    return std::array<double, 10>{x * x * x * x + x * y * y * y + y * y, 4 * x * x * x + y * y * y,
                                  3 * x * y * y + 2 * y, 12 * x * x, 3 * y * y, 6 * x * y + 2, 24 * x, 0.0,
                                  6 * y, 6 * x};
  });
  auto evaluator = space->make_evaluator();
  PointValues geometry;
  FunctionValues u;
  double err = 0;
  for (int e = 0; e < space->num_elements(); ++e) {
    evaluator->evaluate_function(e, *space->quadrature(e, 4), c, update_values | update_gradients | update_hessians,
                                 geometry, u);
    for (int k = 0; k < geometry.num_points(); ++k) {
      const double x = geometry.x(0, k), y = geometry.x(1, k);
      err = std::max({err, std::abs(u.value(k) - (x * x * x * x + x * y * y * y + y * y)),
                      std::abs(u.dx(k) - (4 * x * x * x + y * y * y)), std::abs(u.dy(k) - (3 * x * y * y + 2 * y)),
                      std::abs(u.dxx(k) - 12 * x * x), std::abs(u.dxy(k) - 3 * y * y),
                      std::abs(u.dyy(k) - (6 * x * y + 2))});
    }
  }
  EXPECT_LT(err, 1e-8);
}

/// The default path on B-splines: Σ N_i = 1, so u_h = 1 with zero derivatives on a curved patch.
TEST(FunctionEvaluation, BsplinePartitionOfUnity) {
  const SpacePtr space = annulus_bspline();
  auto evaluator = space->make_evaluator();
  PointValues geometry;
  FunctionValues u;
  const Eigen::VectorXd ones = Eigen::VectorXd::Ones(space->dimension());
  for (int e = 0; e < space->num_elements(); ++e) {
    evaluator->evaluate_function(e, *space->quadrature(e, 6), ones, update_values | update_gradients | update_hessians,
                                 geometry, u);
    EXPECT_LT((u.value.array() - 1.0).abs().maxCoeff(), 1e-13);
    EXPECT_LT(u.dx.cwiseAbs().maxCoeff() + u.dy.cwiseAbs().maxCoeff(), 1e-11);
    EXPECT_LT(u.dxx.cwiseAbs().maxCoeff() + u.dxy.cwiseAbs().maxCoeff() + u.dyy.cwiseAbs().maxCoeff(), 1e-9);
  }
}

TEST(FunctionEvaluation, Ws4FastPathMatchesDefault) { check_function_paths(*perturbed_ws4(2), 8); }
TEST(FunctionEvaluation, TmeshFastPathMatchesDefault) { check_function_paths(*graded_tmesh(), 10); }
TEST(FunctionEvaluation, BsplineFastPathMatchesDefault) { check_function_paths(*annulus_bspline(), 8); }
TEST(IntegrateValues, Ws4FastPathMatchesDefault) { check_integrate_paths(*perturbed_ws4(2), 8); }
TEST(IntegrateValues, BsplineMatchesValueTable) { check_integrate_paths(*annulus_bspline(), 8); }
TEST(AssemblerLoad, Ws4MatchesElementValues) { check_load(*perturbed_ws4(2), 8); }
TEST(AssemblerLoad, BsplineMatchesElementValues) { check_load(*annulus_bspline(), 8); }
TEST(FunctionEvaluation, G1FastPathMatchesDefault) { check_function_paths(*g1_three_patches(), 10); }
TEST(FunctionEvaluation, G1FourSplitFastPathMatchesDefault) { check_function_paths(*g1_4split_fan(), 10); }
TEST(IntegrateValues, G1MatchesValueTable) { check_integrate_paths(*g1_three_patches(), 10); }
TEST(IntegrateValues, G1FourSplitMatchesValueTable) { check_integrate_paths(*g1_4split_fan(), 10); }
TEST(AssemblerLoad, G1MatchesElementValues) { check_load(*g1_three_patches(), 10); }

}  // namespace
}  // namespace iga
