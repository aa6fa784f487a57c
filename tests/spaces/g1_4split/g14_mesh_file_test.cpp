// Mesh files as input of the 4-split G1 space (the g1 space's readers): a Gmsh .geo meshed with
// recombined quads solves the clamped plate with a C1 solution; a mesh with triangles is refused,
// naming the triangle and pointing to the g1 space.
#include <gtest/gtest.h>

#include "config/errors.hpp"
#include "solver/solve_problem.hpp"
#include "tests/support/test_support.hpp"

using namespace iga;

namespace {

const std::string kDomains = std::string(IGA_SOURCE_DIR) + "/configs/domains/";

std::string yaml(const std::string& domain) {
  return "problem: {pde: biharmonic, exact: \"sin(2*x+0.3)*cos(3*y-0.2)\", boundary: {all: clamped}}\n"
         "domain: " + domain + "\nspace: {type: g1_4split, degree: 5}\n";
}

}  // namespace

TEST(G14MeshFile, GmshRecombinedQuadsSolveTheClampedPlate) {
  const std::string text =
      yaml("{type: mesh_file, file: " + kDomains + "g1_pentagon_quads.geo, mesh_size: 0.8, recombine: true}");
  const SpacePtr s = test::space_from_yaml(text, 1);
  EXPECT_EQ(s->type(), "g1_4split");
  const LevelResult r = solve_problem(*s, test::problem_from_yaml(text), SolverKind::cholmod).result;
  EXPECT_LT(*r.h2, 0.1);
  ASSERT_TRUE(r.g1_jump.has_value());
  EXPECT_LT(*r.g1_jump, 1e-10);
}

TEST(G14MeshFile, TrianglesAreRefusedWithThePointerToG1) {
  try {
    test::space_from_yaml(yaml("{type: mesh_file, file: " + kDomains + "g1_valence5_plate.obj}"));
    FAIL() << "a mesh with triangles was accepted";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("triangle"), std::string::npos) << m;
    EXPECT_NE(m.find("g1 space"), std::string::npos) << m;
  }
}
