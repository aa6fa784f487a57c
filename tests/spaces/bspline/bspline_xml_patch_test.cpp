// The B-spline space on one patch read from G+Smo's XML format: configs/domains/quarter_annulus.xml
// (a TensorNurbs2) is the built-in quarter annulus, so spaces and errors agree; several patches
// are refused with the reason.
#include <gtest/gtest.h>

#include "tests/support/input_error.hpp"
#include "tests/support/test_support.hpp"

namespace iga {
namespace {

const std::string problem = R"yaml(
problem:
  pde: poisson
  exact: "sin(x)*exp(y)"
  boundary: {all: dirichlet}
space: {type: bspline, degree: 3, elements: [2, 4]}
)yaml";

TEST(BSplineXmlPatch, QuarterAnnulusMatchesTheBuiltIn) {
  const std::string builtin = problem + "domain: {type: quarter_annulus, inner: 1, outer: 2}\n";
  const std::string xml =
      problem + "domain: {type: mesh_file, file: " + std::string(IGA_SOURCE_DIR) + "/configs/domains/quarter_annulus.xml}\n";
  const ProblemSpec p = test::problem_from_yaml(builtin);
  for (int level = 0; level < 2; ++level) {
    const SpacePtr a = test::space_from_yaml(builtin, level), b = test::space_from_yaml(xml, level);
    ASSERT_EQ(a->dimension(), b->dimension());
    const LevelResult ra = solve_problem(*a, p, SolverKind::cholmod).result;
    const LevelResult rb = solve_problem(*b, p, SolverKind::cholmod).result;
    std::printf("level %d: dofs %d  L2 %.6e / %.6e  H1 %.6e / %.6e\n", level, a->dimension(), *ra.l2, *rb.l2, *ra.h1, *rb.h1);
    // The file's weight 0.7071067811865476 and the built-in 1/sqrt(2) differ by at most an ulp.
    EXPECT_NEAR(*rb.l2, *ra.l2, 1e-8 * *ra.l2);
    EXPECT_NEAR(*rb.h1, *ra.h1, 1e-8 * *ra.h1);
  }
}

TEST(BSplineXmlPatch, RefusesMultipatchFilesAndOtherFormats) {
  const std::string multi =
      problem + "domain: {type: mesh_file, file: " + std::string(IGA_SOURCE_DIR) + "/configs/domains/3p_square.xml}\n";
  std::string msg = test::input_error([&] { test::space_from_yaml(multi); });
  EXPECT_NE(msg.find("domain.file: "), std::string::npos) << msg;
  EXPECT_NE(msg.find("3p_square.xml: 3 patches: the bspline space takes a single patch"), std::string::npos) << msg;
  msg = test::input_error([&] { test::space_from_yaml(problem + "domain: {type: mesh_file, file: square.obj}\n"); });
  EXPECT_NE(msg.find("the bspline space reads one patch from a G+Smo .xml file (got 'square.obj'"), std::string::npos) << msg;
}

}  // namespace
}  // namespace iga
