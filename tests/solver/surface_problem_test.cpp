// laplace_beltrami as a config states it: input errors for mismatched domains, and the source
// computed through the surface's normal and curvature.
#include <gtest/gtest.h>

#include <cmath>

#include "config/errors.hpp"
#include "solver/surface_problem.hpp"
#include "tests/support/test_support.hpp"

namespace iga {
namespace {

const char* kSphere = R"(
problem: {pde: laplace_beltrami, exact: "x*y"}
domain: {type: surface, mesh: icosphere, level: 0}
space: {type: surface, degree: 2}
)";

TEST(SurfaceProblem, SourceOfASphericalHarmonicOnTheUnitSphere) {
  // On the unit sphere (n = x, H = 2): −Δ_Γ(xy) + xy = 7xy, and −Δ_Γx + x = 3x.
  const SurfaceSource f = surface_source(test::problem_from_yaml(kSphere));
  const Eigen::Vector3d x = Eigen::Vector3d(0.3, -0.5, 0.8).normalized();
  EXPECT_NEAR(f(x, x, 2.0), 7 * x.x() * x.y(), 1e-14);
  EXPECT_NEAR(f(x, -x, -2.0), 7 * x.x() * x.y(), 1e-14);  // independent of the orientation
  const SurfaceSource g =
      surface_source(test::problem_from_yaml("problem: {pde: laplace_beltrami, exact: \"x\"}"));
  EXPECT_NEAR(g(x, x, 2.0), 3 * x.x(), 1e-14);
}

TEST(SurfaceProblem, RejectsMismatchedDomainsAndKeys) {
  const auto study = [](const std::string& yaml) {
    return parse_study(ConfigNode::load_string(yaml, "t.yaml"), "t.yaml", 0, "");
  };
  EXPECT_NO_THROW(study(kSphere));
  // A planar domain with laplace_beltrami, and a surface with a planar problem.
  EXPECT_THROW(study(R"(
problem: {pde: laplace_beltrami, exact: "x*y"}
domain: {type: rectangle, min: [0, 0], max: [1, 1]}
space: {type: bspline, degree: 2}
)"),
               InputError);
  EXPECT_THROW(study(R"(
problem: {pde: poisson, exact: "x*y", boundary: {all: dirichlet}}
domain: {type: surface, mesh: icosphere, level: 0}
space: {type: surface, degree: 2}
)"),
               InputError);
  // Boundary conditions are not a key of laplace_beltrami.
  EXPECT_THROW(study(R"(
problem: {pde: laplace_beltrami, exact: "x*y", boundary: {all: dirichlet}}
domain: {type: surface, mesh: icosphere, level: 0}
space: {type: surface, degree: 2}
)"),
               InputError);
  EXPECT_THROW(test::problem_from_yaml("problem: {pde: laplace_beltrami}"), InputError);
  EXPECT_THROW(test::problem_from_yaml("problem: {pde: laplace_beltrami, exact: \"x\", reaction: -1}"), InputError);
  EXPECT_EQ(test::problem_from_yaml("problem: {pde: laplace_beltrami, exact: \"x\", reaction: 0}").reaction, 0.0);
}

TEST(SurfaceProblem, OpenSurfacesAreAnInputError) {
  const std::string yaml = R"(
problem: {pde: laplace_beltrami, exact: "x*y"}
domain: {type: surface, mesh: height_field}
space: {type: surface, degree: 2}
)";
  const SpacePtr space = test::space_from_yaml(yaml);
  EXPECT_FALSE(space->boundary_edges("all").empty());
  EXPECT_THROW(solve_problem(*space, test::problem_from_yaml(yaml), SolverKind::cholmod), InputError);
}

}  // namespace
}  // namespace iga
