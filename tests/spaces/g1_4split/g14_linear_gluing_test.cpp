// Linear gluing data (blending: linear, a(t) = A0 (1 − t) − A1 t): the dimension of the paper's
// bicubic remark (72 on fan3 at k = 3), nested refinement separable at degree 4 with the optimal
// rates, the optimal H2 rate at degree 5 on the valence-5 pentagon (where q1 loses half an order),
// and the refusal at interior crossing vertices where opposite edges have different slopes.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "config/errors.hpp"
#include "spaces/g1_4split/g1_4split_basis.hpp"
#include "spaces/g1_4split/g1_4split_meshes.hpp"
#include "spaces/g1_4split/line_gluing.hpp"
#include "tests/support/test_support.hpp"

using namespace iga;

namespace {

std::string plate(const std::string& domain, const std::string& space) {
  return "problem: {pde: biharmonic, exact: \"sin(2*x+0.3)*cos(3*y)\", boundary: {all: clamped}}\n"
         "domain: {type: multipatch, name: " + domain + "}\nspace: {type: g1_4split, " + space + "}\n";
}

}  // namespace

TEST(G14LinearGluing, DimensionsBruteForceFormulaAndLocalBasis) {
  // fan3 at k = 3: 72 (notes §9.2, the paper's bicubic example with linear gluing).
  struct Row {
    const char* mesh;
    int k, dim;
  };
  for (const Row r : {Row{"fan3", 3, 72}, Row{"fan3", 4, 0}, Row{"fan5", 4, 0}, Row{"fan6", 5, 0}}) {
    const QuadTopology t = quad_topology(g14_domain(r.mesh));
    const auto g = symmetric_gluing(t, Blending::linear);
    const int brute = nullspace_dimension(Eigen::MatrixXd(global_constraints(t, g, SplitBSpline(r.k, 1))));
    if (r.dim > 0) EXPECT_EQ(brute, r.dim) << r.mesh;
    EXPECT_EQ(g14_dimension_formula(t, g, r.k, 1), brute) << r.mesh << " k=" << r.k;
    EXPECT_EQ(build_g14_basis(t, g, r.k, 1).dimension(), brute) << r.mesh << " k=" << r.k;
    // Nested: the refined mesh with inherited gluing is separable at the same degree, and the local
    // basis spans the whole null space there too.
    const QuadTopology fine = t.refined();
    const auto gf = inherited_gluing(t, g, fine);
    const int brute_fine = nullspace_dimension(Eigen::MatrixXd(global_constraints(fine, gf, SplitBSpline(r.k, 1))));
    if (r.k >= 4) EXPECT_EQ(build_g14_basis(fine, gf, r.k, 1).dimension(), brute_fine) << r.mesh;
  }
}

TEST(G14LinearGluing, QuarticNestedPoissonOnFan3IsOptimal) {
  const test::Rates r = test::last_rates(
      "problem: {pde: poisson, exact: \"sin(2*x+0.3)*cos(3*y)\", boundary: {all: dirichlet}}\n"
      "domain: {type: multipatch, name: fan3}\nspace: {type: g1_4split, degree: 4, blending: linear}\n",
      4);
  EXPECT_GT(r.l2, 4.8);
  EXPECT_GT(r.h1, 3.8);
}

TEST(G14LinearGluing, PentagonPlateOptimalAtDegrees4And5) {
  const test::Rates r4 = test::last_rates(plate("fan5", "degree: 4, blending: linear"), 4);
  EXPECT_GT(r4.h2, 2.9);
  const test::Rates r5 = test::last_rates(plate("fan5", "degree: 5, blending: linear"), 4);
  EXPECT_GT(r5.l2, 5.6);
  EXPECT_GT(r5.h2, 3.9);  // q1 gives 3.4–3.65 here (traces of degree k − 1 along the coarse edges)
}

TEST(G14LinearGluing, RefusedAtCrossingVerticesWithDifferentSlopes) {
  // The hexagon split once: its spoke midpoints are crossing vertices between the valence-6 centre
  // (A = 1) and a straight boundary point (A = 0), so per-edge linear data have outward slopes −1
  // and 0 on opposite edges there.
  try {
    test::space_from_yaml(plate("fan6s", "degree: 5, blending: linear"));
    FAIL() << "linear gluing accepted at crossing vertices with different slopes";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("space.blending"), std::string::npos) << m;
    EXPECT_NE(m.find("crossing"), std::string::npos) << m;
  }
  EXPECT_EQ(twist_incompatible_vertex(cube_topology(), symmetric_gluing(cube_topology(), Blending::linear)), -1);
  // The split tetrahedron: its crossing vertices lie between two valence-3 vertices on both lines,
  // so the slopes agree and the twists close: accepted, and the space is the brute-force null space.
  const QuadTopology t = split_tetrahedron_topology();
  const auto g = symmetric_gluing(t, Blending::linear);
  EXPECT_EQ(twist_incompatible_vertex(t, g), -1);
  EXPECT_EQ(build_g14_basis(t, g, 4, 1).dimension(),
            nullspace_dimension(Eigen::MatrixXd(global_constraints(t, g, SplitBSpline(4, 1)))));
}
