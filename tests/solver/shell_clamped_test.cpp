// Clamped edges of a Kirchhoff–Love shell by Nitsche's method (assembly/shell_rotation.hpp): the
// clamped square plate under a uniform load gives Timoshenko's centre deflection, and the answer
// hardly depends on the penalty (the method is consistent: a penalty alone would not be); symmetry
// planes on a quarter of the pinched cylinder approach the whole cylinder's answer.
#include <gtest/gtest.h>

#include <Eigen/SparseCholesky>
#include <cmath>
#include <cstdio>
#include <string>

#include "assembly/shell_rotation.hpp"
#include "solver/shell_problem.hpp"
#include "solver/study_functionals.hpp"
#include "tests/support/pinched_cylinder.hpp"
#include "tests/support/test_support.hpp"

namespace iga {
namespace {

std::string clamped_plate_yaml() {
  // D = E t³ / (12 (1 − ν²)) = 1 with E = 1e6, ν = 0.3.
  return std::string(R"yaml(
problem:
  pde: kirchhoff_love_shell
  material: {youngs_modulus: 1e6, poisson_ratio: 0.3, thickness: 0.02218575500393935}
  load: [0, 0, 1]
  boundary: {all: {fixed: [x, y, z], rotation: held}}
domain: {type: surface_patch, file: )yaml") +
         IGA_SOURCE_DIR + R"yaml(/configs/domains/square-10-3d.xml}
space: {type: bspline, degree: 3, elements: [2, 2]}
output:
  functionals:
    w: {point: [5, 5, 0], component: z}
)yaml";
}

TEST(ShellClamped, SquarePlateGivesTimoshenkosDeflection) {
  // Timoshenko & Woinowsky-Krieger, Theory of Plates and Shells (clamped rectangular plates, b/a = 1): the clamped square plate
  // of side a under a uniform load q deflects w_max = 0.00126532 q a⁴ / D at its centre (independent
  // of ν: the ν term of a clamped plate's energy integrates to zero). a = 10, q = 1, D = 1: 12.6532.
  const std::string yaml = clamped_plate_yaml();
  const ConfigNode root = ConfigNode::load_string(yaml, "test.yaml");
  const ProblemSpec problem = parse_problem(root["problem"]);
  const SpacePtr space = make_space(root["domain"], root["space"], 3);  // 16 × 16 elements
  const std::vector<FunctionalSpec> f = parse_functionals(root["output"]["functionals"], *space, 3);
  const DiscreteSolution s = solve_problem(*space, problem, SolverKind::cholmod);
  const double w = evaluate_functionals(f, *space, s.coefficients).at(0);
  std::printf("16 x 16 cubic: w(5, 5) = %.9f (Timoshenko 12.6532)\n", w);
  // Six digits given; the discretisation's own error at this level is 1e-5 relative (levels 3-4
  // change w by 1e-4, order 4: docs/shells.md).
  EXPECT_NEAR(w, 12.6532, 2e-4);
}

TEST(ShellClamped, NitscheIsConsistentAcrossPenalties) {
  // The same plate at 8 × 8 elements with the penalty η scaled by 1/4, 1 and 10: a consistent
  // method converges to the same solution for every stable η, so w changes by far less than the
  // discretisation error (a pure penalty would shift it by O(1/η)).
  const std::string yaml = clamped_plate_yaml();
  const ConfigNode root = ConfigNode::load_string(yaml, "test.yaml");
  const ProblemSpec problem = parse_problem(root["problem"]);
  const SpacePtr space = make_space(root["domain"], root["space"], 2);
  const std::vector<FunctionalSpec> f = parse_functionals(root["output"]["functionals"], *space, 3);
  const ShellFormulation shell(*space, problem);
  const Eigen::VectorXd b = shell.load(WorkShare{});
  const Constraints c = shell.constraints();
  const SparseMatrix energy = shell.Formulation::matrix(shell.terms()).high;
  const double eta = 10.0 * 16;  // ShellFormulation's 10 (p + 1)²
  double w[3];
  const double scale[3] = {0.25, 1.0, 10.0};
  for (int k = 0; k < 3; ++k) {
    const SparseMatrix K = energy + shell_rotation_nitsche(*space, space->boundary_edges("all"), problem.shell->material,
                                                           scale[k] * eta, shell.quadrature_degree());
    SparseMatrix A;
    Eigen::VectorXd rhs;
    reduce_system(K, b, c, A, rhs);
    const Eigen::SimplicialLDLT<SparseMatrix> ldlt(A);
    ASSERT_EQ(ldlt.info(), Eigen::Success);
    const Eigen::VectorXd u = expand_solution(ldlt.solve(rhs), c);
    w[k] = evaluate_functionals(f, *space, u).at(0);
    std::printf("eta x %.2f: w(5, 5) = %.9f\n", scale[k], w[k]);
  }
  const double discretisation = std::abs(w[1] - 12.6532);  // 1.6e-3 at 8 × 8
  EXPECT_LT(std::abs(w[0] - w[1]), 0.5 * discretisation);
  EXPECT_LT(std::abs(w[2] - w[1]), 0.5 * discretisation);
}

double crown_deflection(const std::string& yaml, int level) {
  const ConfigNode root = ConfigNode::load_string(yaml, "test.yaml");
  const ProblemSpec problem = parse_problem(root["problem"]);
  const SpacePtr space = make_space(root["domain"], root["space"], level);
  const std::vector<FunctionalSpec> f = parse_functionals(root["output"]["functionals"], *space, 3);
  const DiscreteSolution s = solve_problem(*space, problem, SolverKind::cholmod);
  return evaluate_functionals(f, *space, s.coefficients).at(0);
}

TEST(ShellSymmetryPlanes, QuarterCylinderApproachesTheWholeOne) {
  // The pinched cylinder whole (periodic patch: symmetric by construction) and on a quarter with
  // two symmetry planes held by Nitsche ({fixed: [normal component], rotation: held}), on the same
  // mesh per level. The weak symmetry's error is at most that of the energy norm, O(h^{p−1}) = O(h²)
  // for cubics: the difference of the two must fall at least 4× from level 1 to level 2
  // (measured 1.3e-2 and 9.4e-4 relative, docs/shells.md).
  const std::string common = R"(
space: {type: bspline, degree: 3, elements: [8, 4]}
output:
  functionals:
    w: {point: [300, 0, 300], component: z}
)";
  const std::string whole = std::string(test::kPinchedCylinderProblemAndDomain) + common;
  std::string quarter = R"(
problem:
  pde: kirchhoff_love_shell
  material: {youngs_modulus: 3e6, poisson_ratio: 0.3, thickness: 3}
  point_loads:
    - {point: [300, 0, 300], force: [0, 0, -0.5]}
  boundary:
    bottom: {fixed: [y, z]}
    top: {fixed: [x], rotation: held}
    left: {fixed: [z], rotation: held}
    right: {fixed: [z], rotation: held}
domain: {type: surface_patch, shape: cylinder, radius: 300, length: 300, half_angle: 90})" + common;
  quarter.replace(quarter.find("elements: [8, 4]"), 16, "elements: [4, 2]");
  double difference[2];
  for (int level = 1; level <= 2; ++level) {
    const double w = crown_deflection(whole, level), q = crown_deflection(quarter, level);
    difference[level - 1] = std::abs(q - w) / std::abs(w);
    std::printf("level %d: whole %.9e, quarter %.9e, relative difference %.2e\n", level, w, q, difference[level - 1]);
  }
  EXPECT_LT(difference[1], difference[0] / 4);
  EXPECT_LT(difference[1], 1e-2);
}

}  // namespace
}  // namespace iga
