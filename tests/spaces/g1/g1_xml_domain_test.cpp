// A domain from G+Smo's XML format is the same domain as the built-in one: the shipped
// configs/domains/3p_square.xml gives the built-in 3p_square's space and, level by level, its errors.
#include <gtest/gtest.h>

#include <cmath>

#include "tests/support/test_support.hpp"

namespace iga {
namespace {

const std::string problem = R"yaml(
problem:
  pde: biharmonic
  exact: "(cos(2*pi*x)-1)*(cos(2*pi*y)-1)"
  boundary: {all: clamped}
)yaml";

std::string with_domain(const std::string& domain, const std::string& space) {
  return problem + "domain: " + domain + "\nspace: " + space + "\n";
}

TEST(G1XmlDomain, ThreePatchSquareMatchesTheBuiltIn) {
  const std::string xml = "{type: mesh_file, file: " + std::string(IGA_SOURCE_DIR) + "/configs/domains/3p_square.xml}";
  for (const std::string space : {"{type: g1, degree: 5}", "{type: g1_4split, degree: 5}"}) {
    const std::string builtin_yaml = with_domain("{type: multipatch, name: 3p_square}", space);
    const std::string xml_yaml = with_domain(xml, space);
    const ProblemSpec p = test::problem_from_yaml(builtin_yaml);
    for (int level = 0; level < 2; ++level) {
      const SpacePtr a = test::space_from_yaml(builtin_yaml, level), b = test::space_from_yaml(xml_yaml, level);
      ASSERT_EQ(a->dimension(), b->dimension()) << space;
      ASSERT_EQ(a->num_elements(), b->num_elements()) << space;
      const LevelResult ra = solve_problem(*a, p, SolverKind::cholmod).result;
      const LevelResult rb = solve_problem(*b, p, SolverKind::cholmod).result;
      std::printf("%s level %d: dofs %d  L2 %.6e / %.6e  H2 %.6e / %.6e\n", space.c_str(), level, a->dimension(), *ra.l2,
                  *rb.l2, *ra.h2, *rb.h2);
      // The same space on the same mesh: equal up to the solver's round-off.
      EXPECT_NEAR(*rb.l2, *ra.l2, 1e-8 * *ra.l2);
      EXPECT_NEAR(*rb.h1, *ra.h1, 1e-8 * *ra.h1);
      EXPECT_NEAR(*rb.h2, *ra.h2, 1e-8 * *ra.h2);
    }
  }
}

TEST(G1XmlDomain, PatchesThatAreNotBilinearAreRefusedWithTheReason) {
  const std::string file = test::scratch_file(
      "curved.xml",
      "<xml>\n <Geometry type=\"TensorBSpline2\" id=\"0\">\n  <Basis type=\"TensorBSplineBasis2\">\n"
      "   <Basis type=\"BSplineBasis\" index=\"0\"><KnotVector degree=\"2\">0 0 0 1 1 1</KnotVector></Basis>\n"
      "   <Basis type=\"BSplineBasis\" index=\"1\"><KnotVector degree=\"1\">0 0 1 1</KnotVector></Basis>\n"
      "  </Basis>\n  <coefs geoDim=\"2\">0 0 0.5 -0.1 1 0 0 1 0.5 1.1 1 1</coefs>\n </Geometry>\n</xml>\n");
  const std::string yaml = with_domain("{type: mesh_file, file: " + file + "}", "{type: g1, degree: 5}");
  try {
    test::space_from_yaml(yaml);
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("test.yaml:6:"), std::string::npos) << msg;  // the config place of domain
    EXPECT_NE(msg.find("curved.xml: patch 0, Geometry id 0 (line 2): degree (2, 1)"), std::string::npos) << msg;
    EXPECT_NE(msg.find("not bilinear"), std::string::npos) << msg;
  }
}

}  // namespace
}  // namespace iga
