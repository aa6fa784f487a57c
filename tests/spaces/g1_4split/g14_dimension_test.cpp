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
