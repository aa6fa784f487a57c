// max_gradient_jump of piecewise polynomials on PatchMeshes and of G1Space functions: exact values
// for C0-only tents (so the check can fail), round-off for smooth and G1 functions.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>

#include "spaces/g1/g1_space.hpp"
#include "tests/support/patch_gradient_jump.hpp"
#include "spaces/g1/multipatch_domains.hpp"

using namespace iga;

namespace {

using P = Point2;

/// Bernstein coefficients of degree (k,k) of the bilinear function with corner values c[0..3]
/// (corners (0,0),(1,0),(1,1),(0,1)): for a bilinear function they are its values at (i/k, j/k).
Eigen::VectorXd bilinear_coefficients(int k, const std::array<double, 4>& c) {
  Eigen::VectorXd out((k + 1) * (k + 1));
  for (int j = 0; j <= k; ++j)
    for (int i = 0; i <= k; ++i) {
      const double u = double(i) / k, v = double(j) / k;
      out[i + j * (k + 1)] = c[0] * (1 - u) * (1 - v) + c[1] * u * (1 - v) + c[2] * u * v + c[3] * (1 - u) * v;
    }
  return out;
}

/// [0,2] x [0,1] as two unit squares (interface x = 1), scaled by `s` in y.
PatchMesh two_squares(double s) {
  return mesh_from_patches({PatchCorners{P(0, 0), P(1, 0), P(1, s), P(0, s)},
                            PatchCorners{P(1, 0), P(2, 0), P(2, s), P(1, s)}},
                           "two_squares");
}

}  // namespace

TEST(G1GradientJump, TentHasJumpTwoAcrossTheInterface) {
  // u = 1 - |x - 1|: gradients (1,0) and (-1,0), jump exactly 2 along the whole interface.
  const PatchMesh m = two_squares(0.5);
  for (int k : {1, 3, 5}) {
    std::vector<Eigen::VectorXd> c(2);
    // The corner order of a face is the mesh's own (counterclockwise from corner 0); recompute the
    // tent from physical corner positions to be independent of it.
    for (int f = 0; f < 2; ++f) {
      std::array<double, 4> vals;
      for (int i = 0; i < 4; ++i) vals[i] = 1.0 - std::abs(m.vertex(m.face(f)[i]).x() - 1.0);
      c[f] = bilinear_coefficients(k, vals);
    }
    EXPECT_NEAR(max_gradient_jump(m, k, c), 2.0, 1e-12) << "k = " << k;
  }
}

TEST(G1GradientJump, SmoothFunctionHasNoJump) {
  // u = x + 3y + 2xy is bilinear in physical coordinates on both faces: C-infinity, no jump.
  const PatchMesh m = two_squares(0.5);
  const int k = 4;
  std::vector<Eigen::VectorXd> c(2);
  for (int f = 0; f < 2; ++f) {
    std::array<double, 4> vals;
    for (int i = 0; i < 4; ++i) {
      const P& x = m.vertex(m.face(f)[i]);
      vals[i] = x.x() + 3 * x.y() + 2 * x.x() * x.y();
    }
    c[f] = bilinear_coefficients(k, vals);
  }
  EXPECT_LT(max_gradient_jump(m, k, c), 1e-13);
}

TEST(G1GradientJump, G1FunctionsAtRoundOffAndBrokenOnesNot) {
  const auto mesh = std::make_shared<const PatchMesh>(multipatch_domain("3p_square"));
  const G1Space space(mesh, 5);
  const int k = 5;
  Eigen::VectorXd coef = Eigen::VectorXd::Random(space.dimension());
  const std::optional<double> jump = space.max_gradient_jump(coef);
  ASSERT_TRUE(jump.has_value());
  EXPECT_LT(*jump, 1e-10);

  // The same function plus eps times the C0 piecewise-bilinear hat of the valence-3 vertex
  // (0.6, 0.6): the jump is eps times the hat's own jump, which is of order 1/h.
  int centre = -1;
  for (int v = 0; v < mesh->num_vertices(); ++v)
    if ((mesh->vertex(v) - P(0.6, 0.6)).norm() < 1e-12) centre = v;
  ASSERT_GE(centre, 0);
  std::vector<Eigen::VectorXd> g1(mesh->num_faces()), hat(mesh->num_faces());
  for (int f = 0; f < mesh->num_faces(); ++f) {
    const std::vector<int>& dofs = space.basis().face_dofs[f];
    Eigen::VectorXd local(dofs.size());
    for (std::size_t i = 0; i < dofs.size(); ++i) local[i] = coef[dofs[i]];
    g1[f] = space.basis().extraction[f] * local;
    std::array<double, 4> vals{};
    for (int i = 0; i < 4; ++i) vals[i] = mesh->face(f)[i] == centre ? 1.0 : 0.0;
    hat[f] = bilinear_coefficients(k, vals);
  }
  EXPECT_NEAR(max_gradient_jump(*mesh, k, g1), *jump, 1e-14);
  const double hat_jump = max_gradient_jump(*mesh, k, hat);
  EXPECT_GT(hat_jump, 1.0);  // gradients of size ~1/0.6 on every side, pointing different ways
  for (double eps : {1e-6, 1e-3, 1.0}) {
    std::vector<Eigen::VectorXd> broken(mesh->num_faces());
    for (int f = 0; f < mesh->num_faces(); ++f) broken[f] = g1[f] + eps * hat[f];
    EXPECT_NEAR(max_gradient_jump(*mesh, k, broken), eps * hat_jump, 1e-10 + 1e-9 * eps * hat_jump) << eps;
  }
}

TEST(G1GradientJump, RefinedSpaceStaysAtRoundOff) {
  auto mesh = std::make_shared<const PatchMesh>(multipatch_domain("pentagon").refined().refined());
  const G1Space space(mesh, 5);
  const Eigen::VectorXd coef = Eigen::VectorXd::Random(space.dimension());
  EXPECT_LT(*space.max_gradient_jump(coef), 1e-9);
  EXPECT_EQ(gradient_jump_samples(5), 14);
}
