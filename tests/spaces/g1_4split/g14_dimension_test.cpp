// Dimension of the 4-split G1 space: the local basis, a brute-force nullspace of all C0 + G1 rows
// and the formula of the notes (§7, numbers of §9.1 and §12.8) agree; every basis function
// satisfies every row; the basis has full rank; below the separability degree the construction stops.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "spaces/g1_4split/g1_4split_basis.hpp"
#include "spaces/g1_4split/g1_4split_meshes.hpp"

namespace iga {
namespace {

QuadTopology mesh(const std::string& name) {
  if (name == "cube") return cube_topology();
  if (name == "tetra") return split_tetrahedron_topology();
  if (name == "fan3+") return fan_topology(3, true);
  if (name == "fan5+") return fan_topology(5, true);
  return quad_topology(g14_domain(name));
}

int brute_force(const QuadTopology& t, const std::vector<SplitGluing>& g, int k) {
  const SplitBSpline b(k, 1);
  return nullspace_dimension(Eigen::MatrixXd(global_constraints(t, g, b)));
}

/// Local basis: count, C·B ≈ 0 and full rank.
void check_local(const QuadTopology& t, const std::vector<SplitGluing>& g, int k, int expected) {
  const G14Basis basis = build_g14_basis(t, g, k, 1);
  EXPECT_EQ(basis.dimension(), expected) << t.name() << " k=" << k;
  const Eigen::MatrixXd B(basis.functions);
  const Eigen::MatrixXd C(global_constraints(t, g, basis.bspline));
  // Each row is scaled like its largest entry; each function like its largest coefficient.
  double worst = 0.0;
  const Eigen::MatrixXd CB = C * B;
  for (int r = 0; r < C.rows(); ++r)
    for (int c = 0; c < B.cols(); ++c)
      worst = std::max(worst, std::abs(CB(r, c)) / (C.row(r).cwiseAbs().sum() * B.col(c).cwiseAbs().maxCoeff()));
  EXPECT_LT(worst, 1e-12) << t.name() << " k=" << k;
  Eigen::BDCSVD<Eigen::MatrixXd> svd(B);
  const Eigen::VectorXd s = svd.singularValues();
  EXPECT_GT(s(s.size() - 1), 1e-6 * s(0)) << t.name() << " k=" << k;
}

struct Row {
  const char* mesh;
  int k;
  int dim;
};

TEST(G14Dimension, PaperGluingQ0BruteForceFormulaAndLocalBasis) {
  const Row rows[] = {{"fan3", 4, 141}, {"fan3", 5, 237}, {"fan3", 6, 357},
                      {"fan5", 4, 233}, {"fan5", 5, 393}, {"fan6", 4, 279}, {"fan6", 5, 471},
                      {"grid2x2", 3, 100}, {"grid2x2", 4, 196}, {"grid2x2", 5, 324},
                      {"grid2x2", 6, 484}, {"cube", 4, 192}, {"cube", 5, 360},
                      {"halffan3", 4, 156}, {"halffan3", 5, 256}, {"halffan3", 6, 380}, {"fan3+", 4, 172},
                      {"fan3+", 5, 296}, {"fan3+", 6, 452}, {"fan5+", 5, 451}, {"fan5+", 6, 687},
                      {"tetra", 4, 384}};
  for (const Row& r : rows) {
    const QuadTopology t = mesh(r.mesh);
    const auto g = symmetric_gluing(t, Blending::q0);
    EXPECT_EQ(brute_force(t, g, r.k), r.dim) << r.mesh << " k=" << r.k;
    EXPECT_EQ(g14_dimension_formula(t, g, r.k, 1), r.dim) << r.mesh << " k=" << r.k;
    check_local(t, g, r.k, r.dim);
  }
}

TEST(G14Dimension, BelowSeparabilityBruteForceOnly) {
  // fan3 k=3 (69) and fan5+ k=4 (263) have the formula's dimension but edges that are not separable:
  // the local construction refuses them.
  const QuadTopology fan3 = mesh("fan3"), fan5p = mesh("fan5+");
  const auto g3 = symmetric_gluing(fan3, Blending::q0), g5 = symmetric_gluing(fan5p, Blending::q0);
  EXPECT_EQ(brute_force(fan3, g3, 3), 69);
  EXPECT_EQ(brute_force(fan5p, g5, 4), 263);
  EXPECT_THROW(build_g14_basis(fan3, g3, 3, 1), NotSeparable);
  EXPECT_THROW(build_g14_basis(fan5p, g5, 4, 1), NotSeparable);
  EXPECT_THROW(build_g14_basis(fan5p, symmetric_gluing(fan5p, Blending::q1), 4, 1), NotSeparable);
  // Closed forms of the notes.
  for (int k = 4; k <= 6; ++k) EXPECT_EQ(brute_force(fan3, g3, k), 12 * k * k - 12 * k - 3);
}

TEST(G14Dimension, C1BlendingQ1) {
  const Row rows[] = {{"fan3", 4, 138}, {"fan5", 4, 228}, {"fan6", 4, 273}, {"cube", 4, 192},
                      {"halffan3", 4, 154}, {"fan3+", 4, 168}, {"tetra", 4, 360}, {"fan5+", 5, 0}};
  for (const Row& r : rows) {
    const QuadTopology t = mesh(r.mesh);
    const auto g = symmetric_gluing(t, Blending::q1);
    const int brute = brute_force(t, g, r.k);
    if (r.dim > 0) EXPECT_EQ(brute, r.dim) << r.mesh;
    EXPECT_EQ(g14_dimension_formula(t, g, r.k, 1), brute) << r.mesh;
    check_local(t, g, r.k, brute);
  }
}

TEST(G14Dimension, NestedRefinementKeepsTheSpaceCountedByBruteForce) {
  for (const char* name : {"fan3"}) {
    const QuadTopology coarse = mesh(name);
    const auto g0 = symmetric_gluing(coarse, Blending::q1);
    const QuadTopology fine = coarse.refined();
    const auto g1 = inherited_gluing(coarse, g0, fine);
    const int brute = brute_force(fine, g1, 5);
    check_local(fine, g1, 5, brute);
  }
}

}  // namespace
}  // namespace iga

namespace iga {
namespace {

/// Brute force, formula and local basis on a planar built-in with its own boundary angles.
int planar_dimension(const std::string& name, Blending blending, int k, int r) {
  const PatchMesh m = g14_domain(name);
  const QuadTopology t = quad_topology(m);
  const auto g = symmetric_gluing(t, blending, vertex_angles(m));
  const int brute = nullspace_dimension(Eigen::MatrixXd(global_constraints(t, g, SplitBSpline(k, r))));
  EXPECT_EQ(g14_dimension_formula(t, g, k, r), brute) << name << " k=" << k << " r=" << r;
  return brute;
}

TEST(G14Dimension, PlanarFan3PlusAndFan5Plus) {
  // The extra quad makes s0 an interior valence-3 vertex; its edges to the bent boundary vertices
  // c0, c1 join different gluing values, so q1 needs degree 5 and fan5+ stops at degree 4.
  for (const char* name : {"fan3+", "fan5+"}) {
    const PatchMesh m = g14_domain(name);
    const QuadTopology t = quad_topology(m);
    EXPECT_EQ(t.num_faces(), name[3] - '0' + 1);
    const auto q1 = symmetric_gluing(t, Blending::q1, vertex_angles(m));
    const auto lin = symmetric_gluing(t, Blending::linear, vertex_angles(m));
    const int dq1 = planar_dimension(name, Blending::q1, 5, 1), dlin = planar_dimension(name, Blending::linear, 4, 1);
    std::printf("%s planar: q1 k=5 %d, linear k=4 %d\n", name, dq1, dlin);
    check_local(t, q1, 5, dq1);
    check_local(t, lin, 4, dlin);
    EXPECT_THROW(build_g14_basis(t, q1, 4, 1), NotSeparable) << name;
  }
  // The topological fan5+ (straight boundary rule, A = 0 at the 2-face boundary vertices): its
  // 5–3 edge is not separable at k = 4 with q0 (notes §12.8: 263 by brute force).
  EXPECT_EQ(brute_force(mesh("fan5+"), symmetric_gluing(mesh("fan5+"), Blending::q0), 4), 263);
}

TEST(G14Dimension, C1Blending) {
  // Notes §9.1: with c1 the fan3 dimensions are those of q0 (69, 141, 237, 357 for k = 3..6).
  const QuadTopology fan3 = mesh("fan3");
  const auto g = symmetric_gluing(fan3, Blending::c1);
  for (const auto [k, dim] : {std::pair{4, 141}, std::pair{5, 237}, std::pair{6, 357}}) {
    EXPECT_EQ(brute_force(fan3, g, k), dim) << k;
    EXPECT_EQ(g14_dimension_formula(fan3, g, k, 1), dim) << k;
    check_local(fan3, g, k, dim);
  }
  EXPECT_EQ(brute_force(fan3, g, 3), 69);
  // c1 on edges with equal non-zero end values needs degree 5 (notes §4.5): the cube.
  const QuadTopology cube = mesh("cube");
  const auto gc = symmetric_gluing(cube, Blending::c1);
  EXPECT_THROW(build_g14_basis(cube, gc, 4, 1), NotSeparable);
  const int brute = brute_force(cube, gc, 5);
  std::printf("cube, c1, k=5: %d\n", brute);
  EXPECT_EQ(g14_dimension_formula(cube, gc, 5, 1), brute);
  check_local(cube, gc, 5, brute);
}

TEST(G14Dimension, RegularityTwoAcrossTheSplitLines) {
  // Notes §9.1, q0, r = 2: 99, 183, 291 for k = 4..6; the formula with (2k − r − 3)² face functions
  // and 4k − 2r − 6 per boundary edge.
  const QuadTopology fan3 = mesh("fan3");
  const auto g = symmetric_gluing(fan3, Blending::q0);
  for (const auto [k, dim] : {std::pair{4, 99}, std::pair{5, 183}, std::pair{6, 291}}) {
    EXPECT_EQ(nullspace_dimension(Eigen::MatrixXd(global_constraints(fan3, g, SplitBSpline(k, 2)))), dim) << k;
    EXPECT_EQ(g14_dimension_formula(fan3, g, k, 2), dim) << k;
  }
  // The local construction at r = 2 (q1, grid and fan5) spans the whole null space.
  for (const char* name : {"grid2x2", "fan5"}) {
    const QuadTopology t = mesh(name);
    const auto gq = symmetric_gluing(t, Blending::q1);
    const int brute = nullspace_dimension(Eigen::MatrixXd(global_constraints(t, gq, SplitBSpline(6, 2))));
    EXPECT_EQ(g14_dimension_formula(t, gq, 6, 2), brute) << name;
    EXPECT_EQ(build_g14_basis(t, gq, 6, 2).dimension(), brute) << name;
  }
  EXPECT_EQ(brute_force(mesh("grid2x2"), symmetric_gluing(mesh("grid2x2"), Blending::q1), 4), 196);
}

}  // namespace
}  // namespace iga
