// One section space per direction from the config (`section: [trig, poly]`): a function that is
// trigonometric in x and polynomial in y is solved to round-off by that space and by neither of the
// single-family spaces; the dimension is the formula's; bad lists are config errors.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "solver/errors.hpp"
#include "solver/solve_problem.hpp"
#include "spaces/tmesh/tmesh_space.hpp"
#include "test_support.hpp"

using namespace iga;

namespace {

std::string yaml(const std::string& section, const std::string& frequency = "1") {
  return "problem: {pde: poisson, exact: \"sin(x)*y^3 + cos(x)*y\", boundary: {all: dirichlet}}\n"
         "domain: {type: rectangle, min: [0, 0], max: [3.141592653589793, 2]}\n"
         "space: {type: tmesh, section: " + section + ", frequency: " + frequency +
         ", n: 3, regularity: 1, elements: [2, 2], refine: [[0, 0, 0.5, 0.5]]}\n";
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
  auto error_of = [](const std::string& text) -> std::string {
    try {
      test::space_from_yaml(text);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_NE(error_of(yaml("[trig]")).find("[family in x, family in y]"), std::string::npos);
  EXPECT_NE(error_of(yaml("[trig, poyl]")).find("poly"), std::string::npos);
  EXPECT_NE(error_of(yaml("[trig, poly]", "[1, 0]")).find("frequency must be > 0"), std::string::npos);
  // w h < pi is checked per direction: cells are pi/2 wide and 1 high, so w = 2.5 fails only in x.
  EXPECT_NE(error_of(yaml("[trig, poly]", "2.5")).find("w*h < pi"), std::string::npos);
  EXPECT_EQ(error_of(yaml("[poly, trig]", "2.5")), "");
}
