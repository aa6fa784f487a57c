// Point loads and free shells (solver/shell_problem.hpp, solver/shell_rigid_motions.hpp): a free
// shell under balanced point loads is solved with no reactions at the pinned coefficients (so the
// pins do not matter), orthogonal to the rigid motions, and its strain energy is the loads' work
// Σ F·u(p); the pinched cylinder's compliance rises with the level and stays below the reference.
#include <gtest/gtest.h>

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "solver/shell_problem.hpp"
#include "solver/study_functionals.hpp"
#include "tests/support/pinched_cylinder.hpp"
#include "tests/support/shell_configs.hpp"
#include "tests/support/test_support.hpp"

namespace iga {
namespace {

std::string number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

std::string point_text(const Eigen::Vector3d& p) {
  return "[" + number(p.x()) + ", " + number(p.y()) + ", " + number(p.z()) + "]";
}

/// The image of the reference point r in every element of the space.
std::vector<Eigen::Vector3d> element_points(const Space& space, const Point2& r) {
  const auto evaluator = space.make_evaluator();
  QuadratureRule one;
  one.points = {r};
  one.weights = {0.0};
  PointValues g;
  std::vector<Eigen::Vector3d> out;
  for (int e = 0; e < space.num_elements(); ++e) {
    evaluator->evaluate_geometry(e, one, g);
    out.push_back(g.x3.col(0));
  }
  return out;
}

TEST(ShellFreeShell, BalancedPointLoadsOnTheCubeNeedNoReactions) {
  // The closed 4-split cube (quintic) is isoparametric: all six rigid motions are discrete
  // (shell_test.cpp), so pinning one coefficient per motion and removing the projection is exact:
  // with loads in equilibrium the solution satisfies K u = b in every row, the pinned ones included
  // (their reactions vanish), which is what makes it independent of the pins.
  const std::string domain = "domain: {type: surface, mesh: cube}\nspace: {type: g1_4split, degree: 5}\n";
  const SpacePtr space = test::space_from_yaml(domain);
  // Two points far apart, pulled apart along the line through them: no resultant force or moment.
  const std::vector<Eigen::Vector3d> points = element_points(*space, Point2(0.3, 0.4));
  const Eigen::Vector3d p1 = points[0];
  std::size_t far = 0;
  for (std::size_t e = 0; e < points.size(); ++e)
    if ((points[e] - p1).norm() > (points[far] - p1).norm()) far = e;
  const Eigen::Vector3d p2 = points[far], d = (p1 - p2).normalized();
  const std::string yaml = R"(
problem:
  pde: kirchhoff_love_shell
  material: {youngs_modulus: 1, poisson_ratio: 0.3, thickness: 0.2}
  point_loads:
    - {point: )" + point_text(p1) + ", force: " + point_text(d) + R"(}
    - {point: )" + point_text(p2) + ", force: " + point_text(-d) + R"(}
)" + domain + R"(
output:
  functionals:
    u1x: {point: )" + point_text(p1) + R"(, component: x}
    u1y: {point: )" + point_text(p1) + R"(, component: y}
    u1z: {point: )" + point_text(p1) + R"(, component: z}
    u2x: {point: )" + point_text(p2) + R"(, component: x}
    u2y: {point: )" + point_text(p2) + R"(, component: y}
    u2z: {point: )" + point_text(p2) + R"(, component: z}
)";
  const ConfigNode root = ConfigNode::load_string(yaml, "test.yaml");
  const ProblemSpec problem = parse_problem(root["problem"]);
  const ShellFormulation f(*space, problem);
  const Eigen::VectorXd b = f.load(WorkShare{});
  const Constraints c = f.constraints();
  EXPECT_EQ(f.free_motions().count(), 6);
  EXPECT_EQ(f.pinned().size(), 6u);
  EXPECT_EQ(c.constrained.size(), 6u);

  const DiscreteSolution s = solve_problem(*space, problem, SolverKind::cholmod);
  const Eigen::VectorXd& u = s.coefficients;
  const SparseMatrix K = f.matrix(f.terms()).high;
  // Rounding of a direct solve: ε ‖K‖ ‖u‖; a reaction from an unbalanced load or an inexact kernel
  // would be of the order of the load itself.
  const double rounding = 1e-12 * K.norm() * u.norm();
  const Eigen::VectorXd residual = K * u - b;
  double pinned_residual = 0;
  for (int i : f.pinned()) pinned_residual = std::max(pinned_residual, std::abs(residual(i)));
  std::printf("|b| %.3e, |K||u| %.3e, residual %.3e, at the pins %.3e\n", b.norm(), K.norm() * u.norm(),
              residual.norm(), pinned_residual);
  EXPECT_LT(residual.norm(), rounding);
  EXPECT_LT(pinned_residual, 1e-9 * b.norm());

  // M-orthogonal to the rigid motions.
  const RigidMotionBasis& rm = f.rigid_motion_basis();
  const Eigen::VectorXd moments = rm.moments.transpose() * u;
  EXPECT_LT(moments.norm(), 1e-12 * rm.moments.norm() * u.norm());
  // Adding a rigid motion and removing the projection gives the same coefficients back.
  Eigen::VectorXd moved = u + rm.coefficients * test::random_vector(6, 7);
  remove_rigid_motions(rm, moved);
  EXPECT_LT((moved - u).norm(), 1e-12 * u.norm());

  // The strain energy is the loads' work: a(u, u) = Σ F·u(p), u(p) evaluated at the points.
  const std::vector<double> v =
      evaluate_functionals(parse_functionals(root["output"]["functionals"], *space, 3), *space, u);
  const double work = d.dot(Eigen::Vector3d(v[0], v[1], v[2])) - d.dot(Eigen::Vector3d(v[3], v[4], v[5]));
  const double energy = u.dot(K * u);
  std::printf("a(u, u) %.15e, work %.15e\n", energy, work);
  EXPECT_GT(work, 0.0);
  EXPECT_NEAR(energy, work, 1e-10 * work);
}

TEST(ShellPinchedCylinder, CompliancesRiseBelowTheReference) {
  // Pinched cylinder with rigid diaphragms (note §3; 1.82488e-5 under each unit load): the work of
  // the loads is 2 |u_z(p)| = a(u_h, u_h), which for conforming nested spaces rises with the level
  // and stays below the exact Kirchhoff–Love value (which lies 0.17 % above 1.82488e-5: level 5
  // already gives 1.82697e-5, docs/shells.md). The full periodic cylinder, cubic, levels 1 and 2 of
  // configs/shell-pinched-cylinder.yaml (660 and 2052 unknowns; level 2 is 12 % low).
  const std::string yaml = std::string(test::kPinchedCylinderProblemAndDomain) + R"(
space: {type: bspline, degree: 3, elements: [8, 4]}
output:
  functionals:
    top: {point: [300, 0, 300], component: z}
    bottom: {point: [300, 0, -300], component: z}
)";
  const ConfigNode root = ConfigNode::load_string(yaml, "test.yaml");
  const ProblemSpec problem = parse_problem(root["problem"]);
  double previous = 0;
  for (int level = 1; level <= 2; ++level) {
    const SpacePtr space = make_space(root["domain"], root["space"], level);
    const std::vector<FunctionalSpec> f = parse_functionals(root["output"]["functionals"], *space, 3);
    const DiscreteSolution s = solve_problem(*space, problem, SolverKind::cholmod);
    const std::vector<double> v = evaluate_functionals(f, *space, s.coefficients);
    std::printf("level %d: %d unknowns, u_z %.9e / %.9e, energy %.9e\n", level, s.result.dofs, v[0], v[1],
                *s.result.energy);
    EXPECT_NEAR(v[0], -v[1], 1e-9 * std::abs(v[0]));         // the two loads pinch alike
    EXPECT_NEAR(*s.result.energy, -2 * v[0], 1e-9 * *s.result.energy);  // energy = work
    EXPECT_GT(-v[0], previous);
    EXPECT_LT(-v[0], 1.82488e-5);
    previous = -v[0];
  }
  EXPECT_GT(previous, 0.85 * 1.82488e-5);
}

TEST(ShellFreeShell, PinReactionsOnARationalPatchVanishWithRefinement) {
  // The hemisphere zone is a rational patch carrying polynomial B-splines: x, y, z are not in the
  // space, so the rotations are represented by their L2 projections Πr, which have energy. The pins
  // then carry reactions λ with a(u, v) − ℓ(v) = λ·v_pins; for v = Πr, a(u, Πr − r) − ℓ(Πr − r)
  // (a(u, r) = ℓ(r) = 0 for the exact r), at most O(‖Πr − r‖_H2) = O(h^{p−1}) = O(h²): each level
  // must divide them by at least 4 from level 1 to 2 (measured: 0.15, 7.5e-3, 1.2e-4 at levels 1-3,
  // docs/shells.md; level 3 is left out to keep the test cheap).
  const std::string yaml = test::kFreePinchedHemisphere;
  const ConfigNode root = ConfigNode::load_string(yaml, "test.yaml");
  const ProblemSpec problem = parse_problem(root["problem"]);
  double previous = 0;
  for (int level = 1; level <= 2; ++level) {
    const SpacePtr space = make_space(root["domain"], root["space"], level);
    const ShellFormulation f(*space, problem);
    const Eigen::VectorXd b = f.load(WorkShare{});
    f.constraints();
    ASSERT_EQ(f.free_motions().count(), 6);
    const DiscreteSolution s = solve_problem(*space, problem, SolverKind::cholmod);
    // The reactions of the solve itself: the projection removed afterwards (R α) is added back
    // through K R α, which is not zero here.
    const SparseMatrix K = f.matrix(f.terms()).high;
    const RigidMotionBasis& rm = f.rigid_motion_basis();
    Eigen::VectorXd u = s.coefficients;
    // Undo the removal: the solve's u has zero pinned coefficients; u_solve = u + R α with α fixed by them.
    Eigen::MatrixXd at_pins(6, 6);
    Eigen::VectorXd u_pins(6);
    for (int k = 0; k < 6; ++k) {
      at_pins.row(k) = rm.coefficients.row(f.pinned()[k]);
      u_pins(k) = u(f.pinned()[k]);
    }
    u -= rm.coefficients * at_pins.lu().solve(u_pins);
    const Eigen::VectorXd r = K * u - b;
    double reaction = 0, elsewhere = 0;
    for (int i = 0; i < r.size(); ++i) {
      const bool pinned = std::find(f.pinned().begin(), f.pinned().end(), i) != f.pinned().end();
      double& largest = pinned ? reaction : elsewhere;
      largest = std::max(largest, std::abs(r(i)));
    }
    std::printf("level %d: %d unknowns, largest reaction %.3e, residual elsewhere %.3e\n", level, 3 * space->dimension(),
                reaction, elsewhere);
    EXPECT_LT(elsewhere, 1e-12 * K.norm() * u.norm());  // the solve is exact in the free rows (rounding)
    if (level > 1) EXPECT_LT(reaction, previous / 4);
    previous = reaction;
  }
}

}  // namespace
}  // namespace iga
