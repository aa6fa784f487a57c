// Section spaces from the config: one family per direction (`section: [trig, poly]`), where a
// function trigonometric in x and polynomial in y is solved to round-off by that space and by
// neither single-family space; and other families on the base cells of regions (`sections_in`),
// with d_e = 0 edges between them: dimension = formula = brute force, the reduced rate those
// edges cause, and the n >= 2r+3 they need. Bad lists are config errors.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "config/errors.hpp"
#include "solver/solve_problem.hpp"
#include "tests/spaces/tmesh/brute_force_dimension.hpp"
#include "spaces/tmesh/tmesh_space.hpp"
#include "tests/support/test_support.hpp"

using namespace iga;

namespace {

std::string yaml(const std::string& section, const std::string& frequency = "1") {
  return "problem: {pde: poisson, exact: \"sin(x)*y^3 + cos(x)*y\", boundary: {all: dirichlet}}\n"
         "domain: {type: rectangle, min: [0, 0], max: [3.141592653589793, 2]}\n"
         "space: {type: tmesh, section: " + section + ", frequency: " + frequency +
         ", n: 3, regularity: 1, elements: [2, 2], refine: [[0, 0, 0.5, 0.5]]}\n";
}

/// The InputError message building the space of `text` gives, or "" when it builds.
std::string error_of(const std::string& text) {
  try {
    test::space_from_yaml(text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

double l2_error(const std::string& text) {
  const SpacePtr space = test::space_from_yaml(text, 1);
  const DiscreteSolution sol = solve_problem(*space, test::problem_from_yaml(text), SolverKind::cholmod);
  std::printf("%s -> L2 %.3e\n", text.substr(text.find("section:"), 40).c_str(), *sol.result.l2);
  return *sol.result.l2;
}

}  // namespace

TEST(MixedSections, TrigInXPolyInYReproducesSinXTimesCubic) {
  const SpacePtr space = test::space_from_yaml(yaml("[trig, poly]"), 1);
  const TMeshSpace& t = dynamic_cast<const TMeshSpace&>(*space);
  ASSERT_EQ(t.mesh().sections().size(), 2u);
  EXPECT_EQ(t.mesh().sections()[t.mesh().cells()[0].section_s].family, SectionFamily::trigonometric);
  EXPECT_EQ(t.mesh().sections()[t.mesh().cells()[0].section_t].family, SectionFamily::polynomial);
  EXPECT_EQ(t.dimension(), t.mesh().dimension_formula(1, 1));
  // The same mesh with one family has the same dimension (every composite edge keeps d_e = 2).
  EXPECT_EQ(t.dimension(), test::space_from_yaml(yaml("poly"), 1)->dimension());
  EXPECT_LT(l2_error(yaml("[trig, poly]")), 1e-11);
  EXPECT_GT(l2_error(yaml("trig")), 1e-6);
  EXPECT_GT(l2_error(yaml("poly")), 1e-6);
  EXPECT_GT(l2_error(yaml("[poly, trig]")), 1e-6);
  // A frequency per direction: w = 1 in x, any in y (poly ignores it), and w = 2 in x is wrong for sin x.
  EXPECT_LT(l2_error(yaml("[trig, poly]", "[1, 3]")), 1e-11);
  EXPECT_GT(l2_error(yaml("[trig, poly]", "[2, 1]")), 1e-6);
}

TEST(MixedSections, ConfigErrors) {
  EXPECT_NE(error_of(yaml("[trig]")).find("[family in x, family in y]"), std::string::npos);
  EXPECT_NE(error_of(yaml("[trig, poyl]")).find("poly"), std::string::npos);
  EXPECT_NE(error_of(yaml("[trig, poly]", "[1, 0]")).find("frequency must be > 0"), std::string::npos);
  // w h < pi is checked per direction: cells are pi/2 wide and 1 high, so w = 2.5 fails only in x.
  EXPECT_NE(error_of(yaml("[trig, poly]", "2.5")).find("w*h < pi"), std::string::npos);
  EXPECT_EQ(error_of(yaml("[poly, trig]", "2.5")), "");
}

namespace {

/// C1 quintic (n = 5, r = 1) splines on [0, pi]^2, 2 x 2 base cells, the lower-left one trigonometric.
std::string regions_yaml(int n, int r) {
  return "domain: {type: rectangle, min: [0, 0], max: [3.141592653589793, 3.141592653589793]}\n"
         "space: {type: tmesh, section: poly, n: " + std::to_string(n) + ", regularity: " + std::to_string(r) +
         ", elements: [2, 2], sections_in: [{box: [[0, 0], [1.5, 1.5]], section: trig, frequency: 1}]}\n"
         "problem: {pde: poisson, exact: \"sin(x)*sin(y)\", boundary: {all: dirichlet}}\n";
}

}  // namespace

TEST(SectionRegions, TrigBaseCellInAPolySpaceHasTheFormulaAndBruteForceDimension) {
  for (int level : {0, 1}) {
    const SpacePtr space = test::space_from_yaml(regions_yaml(5, 1), level);
    const TMeshSpace& t = dynamic_cast<const TMeshSpace&>(*space);
    int trig_cells = 0;
    for (const TCell& c : t.mesh().cells())
      trig_cells += t.mesh().sections()[c.section_s].family == SectionFamily::trigonometric ? 1 : 0;
    EXPECT_EQ(trig_cells, level == 0 ? 1 : 4);  // the base cell, then its four children
    // Two composite edges (level 0) between the trig cell and its poly neighbours have d_e = 0.
    int reduced = 0;
    for (const CompositeEdge& e : t.mesh().edges()) reduced += e.d == 0 ? 1 : 0;
    EXPECT_GT(reduced, 0);
    EXPECT_EQ(t.dimension(), t.mesh().dimension_formula(1, 1));
    if (level == 0) EXPECT_EQ(t.dimension(), brute_force_dimension(t.mesh(), 1, 1));
  }
  // Across a d_e = 0 edge the traces are only in the common part, the polynomials of degree
  // n - 2 = 3: the mixed space converges like cubics there (L2 rate 4), not like the quintic
  // space of one family (rate 6). Measured levels 0 -> 1: 1.75e-3 -> 1.23e-4 (3.83); all-poly
  // quintic: 2.86e-5 -> 5.43e-7 (5.72).
  const std::string yaml = regions_yaml(5, 1);
  double l2[2];
  for (int level : {0, 1}) {
    const DiscreteSolution sol = solve_problem(*test::space_from_yaml(yaml, level), test::problem_from_yaml(yaml), SolverKind::cholmod);
    l2[level] = *sol.result.l2;
    std::printf("sections_in, level %d: L2 %.3e\n", level, l2[level]);
  }
  const double rate = std::log2(l2[0] / l2[1]);
  EXPECT_GT(rate, 3.5);
  EXPECT_LT(rate, 4.5);
}

TEST(SectionRegions, ConfigErrors) {
  // d_e = 0 edges need n >= 2r + 3.
  EXPECT_NE(error_of(regions_yaml(3, 1)).find("n >= 5"), std::string::npos) << error_of(regions_yaml(3, 1));
  std::string outside = regions_yaml(5, 1);
  outside.replace(outside.find("[[0, 0], [1.5, 1.5]]"), 20, "[[4, 4], [5, 5]]");
  EXPECT_NE(error_of(outside).find("no base cell overlaps"), std::string::npos);
  std::string typo = regions_yaml(5, 1);
  typo.replace(typo.find("frequency: 1}"), 9, "frequncy");
  EXPECT_NE(error_of(typo).find("did you mean 'frequency'"), std::string::npos);
}
