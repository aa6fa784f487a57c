// Graph surfaces from a config (domain: {type: graph, height, over}, spaces/graph/graph_from_config):
// the factory lifts the planar space of `over`, the study runs the surface problems on it, and
// the lifted spaces converge at their planar rates p + 1 / p / p − 1 (a coarse check: the full
// tables are in docs/surface-biharmonic.md and configs/surface-biharmonic-graph-*.yaml).
#include <gtest/gtest.h>

#include <cmath>

#include "config/errors.hpp"
#include "spaces/lifted_space.hpp"
#include "tests/support/gismo_surface_example.hpp"
#include "tests/support/test_support.hpp"

namespace iga {
namespace {

const std::string kClamped =
    "problem: {pde: surface_biharmonic, exact: \"sin(2*x + z)*cos(y)\", boundary: {all: clamped}}\n";

std::string graph(const std::string& over, const std::string& space, const std::string& height = "x^2 - y^2") {
  return "domain: {type: graph, height: \"" + height + "\", over: " + over + "}\nspace: " + space + "\n";
}

TEST(GraphFromConfig, LiftsThePlanarSpaceOfOver) {
  // Same functions and numbering as the planar space on `over`; points on z = g(x, y).
  const std::string over = "{type: rectangle, min: [-0.5, -0.5], max: [0.5, 0.5]}";
  const std::string space = "{type: bspline, degree: 3, elements: [2, 2]}";
  const SpacePtr lifted = test::space_from_yaml(graph(over, space), 1);
  const SpacePtr planar = test::space_from_yaml("domain: " + over + "\nspace: " + space + "\n", 1);
  EXPECT_EQ(lifted->ambient_dimension(), 3);
  EXPECT_EQ(lifted->dimension(), planar->dimension());
  EXPECT_EQ(lifted->dimension(), (4 + 3) * (4 + 3));  // (n + p)² cubic C2 B-splines on 4 × 4 elements
  EXPECT_EQ(lifted->num_elements(), planar->num_elements());
  EXPECT_FALSE(lifted->boundary_edges("all").empty());
  const auto* lift = dynamic_cast<const LiftedSpace*>(lifted.get());
  ASSERT_NE(lift, nullptr);
  const Eigen::Vector3d x = lift->lift(Point2(0.3, -0.2));
  EXPECT_DOUBLE_EQ(x.z(), 0.3 * 0.3 - 0.2 * 0.2);
  // The level-1 space of a study built from the level-0 one (make_space's `coarser`) is the same.
  const SpacePtr level0 = test::space_from_yaml(graph(over, space), 0);
  const ConfigNode root = ConfigNode::load_string(graph(over, space), "test.yaml");
  EXPECT_EQ(make_space(root["domain"], root["space"], 1, level0.get())->dimension(), lifted->dimension());
}

TEST(GraphFromConfig, GismoSourceGivesTheExactSolution) {
  // G+Smo's biharmonic_surface_example: u = z on z = x² − y² over [−0.5, 0.5]², clamped, with
  // their closed form of f = Δ_Γ²z (gsUnstructuredSplines, examples/biharmonic_surface_example.cpp)
  // as a pointwise source. u ∘ X = x² − y² lies in the cubic space, so the discrete solution is z
  // up to the quadrature error of ∫ f v: a wrong f (or a wrong operator, sign, or lifted clamped
  // data) leaves an error of the size of u itself (|z| ≤ 0.25 here).
  const std::string yaml =
      "problem:\n  pde: surface_biharmonic\n  exact: \"z\"\n  reaction: 0\n  boundary: {all: clamped}\n"
      "  source: \"" + std::string(test::kGismoSurfaceSource) + "\"\n" +
      graph("{type: rectangle, min: [-0.5, -0.5], max: [0.5, 0.5]}",
            "{type: bspline, degree: 3, regularity: 2, elements: [2, 2]}");
  const ProblemSpec problem = test::problem_from_yaml(yaml);
  for (int level = 0; level < 3; ++level) {
    const SpacePtr s = test::space_from_yaml(yaml, level);
    const LevelResult r = solve_problem(*s, problem, SolverKind::cholmod).result;
    std::printf("level %d dofs %d  L2 %.3e H1 %.3e H2 %.3e\n", level, s->dimension(), *r.l2, *r.h1, *r.h2);
    EXPECT_LT(*r.l2, 1e-6);
    EXPECT_LT(*r.h2, 1e-4);
  }
}

/// Rates of u = sin(2x + z) cos(y) on z = x² − y² over `over`, clamped, between the last two of
/// `levels` coarse levels; expected p + 1 / p / p − 1 within 0.3 (the brief's tolerance).
void expect_rates(const std::string& over, const std::string& space, int levels, double p) {
  const test::Rates r = test::last_rates(kClamped + graph(over, space), levels);
  std::printf("%s: rates %.2f %.2f %.2f\n", space.c_str(), r.l2, r.h1, r.h2);
  test::expect_rates(r, p + 1, p, p - 1);
}

TEST(GraphFromConfig, LiftedTmeshConvergesAtItsPlanarRates) {
  // Cubic C1 T-mesh splines (n = 3 sections), 4 / 3 / 2; levels 0–3 (measured 3.95 / 3.01 / 2.01).
  expect_rates("{type: rectangle, min: [0, 0], max: [1, 1]}",
               "{type: tmesh, section: poly, n: 3, regularity: 1, elements: [2, 2]}", 4, 3);
}

TEST(GraphFromConfig, LiftedG1FourSplitConvergesAtItsPlanarRates) {
  // Quartic 4-split G1 on 2 × 2 quads, 5 / 4 / 3; levels 0–2 (measured 5.01 / 3.98 / 3.01).
  expect_rates("{type: multipatch, name: grid2x2}", "{type: g1_4split, degree: 4}", 3, 4);
}

TEST(GraphFromConfig, LaplaceBeltramiOnAGraph) {
  // −Δ_Γu + u = f with Dirichlet data on the lifted boundary: cubic C2 B-splines, expected L2 4, H1 3.
  const std::string yaml =
      "problem: {pde: laplace_beltrami, exact: \"sin(2*x + z)*cos(y)\", boundary: {all: dirichlet}}\n" +
      graph("{type: rectangle, min: [0, 0], max: [1, 1]}", "{type: bspline, degree: 3, elements: [2, 2]}",
            "sin(x)*cos(y)");
  const test::Rates r = test::last_rates(yaml, 4);
  EXPECT_NEAR(r.l2, 4.0, 0.3);
  EXPECT_NEAR(r.h1, 3.0, 0.3);
}

TEST(GraphFromConfig, RefusalsNameTheKey) {
  auto error = [](const std::string& yaml) -> std::string {
    try {
      test::space_from_yaml(yaml, 0);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  };
  const std::string square = "{type: rectangle, min: [0, 0], max: [1, 1]}", cubic = "{type: bspline, degree: 3}";
  // A crease off every mesh line and probe point: refused from the expression itself.
  EXPECT_NE(error(graph(square, cubic, "abs(x - 0.3)")).find("domain.height: the height of a graph surface must be smooth"),
            std::string::npos);
  EXPECT_NE(error(graph(square, cubic, "sqrt(x)")).find("g_x is not finite"), std::string::npos);
  EXPECT_NE(error(graph("{type: surface, mesh: open_cube}", "{type: g1_4split, degree: 5}")).find("domain.over.type"),
            std::string::npos);
  EXPECT_EQ(error(graph(square, cubic, "x*y")), "");
}

}  // namespace
}  // namespace iga
