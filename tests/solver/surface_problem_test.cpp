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

/// The message of the InputError `run` throws ("" when it throws none).
template <class Run>
std::string input_error_of(const Run& run) {
  try {
    run();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
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
  // Dirichlet data on a closed surface (it has no boundary): the formulation's check, which the
  // config reader runs on level 0, at the boundary entry.
  const std::string closed = input_error_of([&] {
    study(R"(
problem: {pde: laplace_beltrami, exact: "x*y", boundary: {all: dirichlet}}
domain: {type: surface, mesh: icosphere, level: 0}
space: {type: surface, degree: 2}
)");
  });
  EXPECT_NE(closed.find("t.yaml:2:"), std::string::npos) << closed;
  EXPECT_NE(closed.find("this surface is closed: it has no boundary for Dirichlet data"), std::string::npos) << closed;
  EXPECT_THROW(test::problem_from_yaml("problem: {pde: laplace_beltrami}"), InputError);
  EXPECT_THROW(test::problem_from_yaml("problem: {pde: laplace_beltrami, exact: \"x\", reaction: -1}"), InputError);
  EXPECT_EQ(test::problem_from_yaml("problem: {pde: laplace_beltrami, exact: \"x\", reaction: 0}").reaction, 0.0);
}

TEST(SurfaceProblem, OpenSurfacesNeedDirichletData) {
  const std::string yaml = R"(
problem: {pde: laplace_beltrami, exact: "x*y"}
domain: {type: surface, mesh: height_field}
space: {type: surface, degree: 2}
)";
  const SpacePtr space = test::space_from_yaml(yaml);
  EXPECT_FALSE(space->boundary_edges("all").empty());
  // One check (SurfaceFormulation::check) for a solve and for the config reader.
  const std::string solve = input_error_of([&] {
    solve_problem(*space, test::problem_from_yaml(yaml), SolverKind::cholmod);
  });
  const std::string parse = input_error_of([&] {
    parse_study(ConfigNode::load_string(yaml, "t.yaml"), "t.yaml", 0, "");
  });
  EXPECT_NE(parse.find("this surface has a boundary: give Dirichlet data on it"), std::string::npos) << parse;
  EXPECT_NE(parse.find("t.yaml:2:"), std::string::npos) << parse;
  EXPECT_NE(solve.find("this surface has a boundary: give Dirichlet data on it"), std::string::npos) << solve;
  EXPECT_THROW(test::problem_from_yaml("problem: {pde: laplace_beltrami, exact: \"x\", boundary_value: \"x\"}"),
               InputError);
  EXPECT_THROW(test::problem_from_yaml("problem: {pde: laplace_beltrami, source: \"1\", boundary: {all: dirichlet}}"),
               InputError);
  EXPECT_THROW(test::problem_from_yaml("problem: {pde: laplace_beltrami, exact: \"x\", boundary: {all: neumann}}"),
               InputError);
}

// The note's open height field (18 patches of degree 8), u = g on its boundary curve: the surface
// is the exact geometry (source through its own normal and curvature), so the rates are the
// optimal p+1 (L2) and p (H1) of C0 elements; sub-triangles halve h exactly in the parameter.
TEST(SurfaceProblem, OpenHeightFieldWithDirichletDataConvergesOptimally) {
  for (int p : {2, 3}) {
    SCOPED_TRACE("degree " + std::to_string(p));
    const std::string yaml = R"(
problem: {pde: laplace_beltrami, exact: "x*y + sin(z) + x", boundary: {all: dirichlet}}
domain: {type: surface, mesh: height_field}
space: {type: surface, degree: )" + std::to_string(p) + "}\n";
    const ProblemSpec problem = test::problem_from_yaml(yaml);
    std::vector<double> l2, h1;
    for (int level = 2; level <= 4; ++level) {
      const DiscreteSolution s = solve_problem(*test::space_from_yaml(yaml, level), problem, SolverKind::cholmod);
      l2.push_back(*s.result.l2);
      h1.push_back(*s.result.h1);
    }
    // Rates per halving of the sub-triangles (log2 of error ratios).
    EXPECT_NEAR(std::log2(l2[1] / l2[2]), p + 1, 0.25);
    EXPECT_NEAR(std::log2(h1[1] / h1[2]), p, 0.15);
    EXPECT_GT(std::log2(l2[0] / l2[1]), p + 0.5);
  }
  // Boundary data given separately: zero data for u = z (the height) changes the solution.
  const std::string own = R"(
problem: {pde: laplace_beltrami, source: "1", boundary: {all: dirichlet}, boundary_value: "0"}
domain: {type: surface, mesh: height_field}
space: {type: surface, degree: 2}
)";
  const DiscreteSolution s = solve_problem(*test::space_from_yaml(own, 1), test::problem_from_yaml(own), SolverKind::cholmod);
  EXPECT_GT(s.coefficients.maxCoeff(), 0.0);
  EXPECT_LT(s.coefficients.minCoeff(), 1e-12);
}

}  // namespace
}  // namespace iga
