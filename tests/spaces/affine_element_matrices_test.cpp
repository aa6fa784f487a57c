/// @file
/// The closed-form arithmetic shared by WS4, T-mesh and B-spline spaces: the weights of each form
/// under an affine map, their two combinations (general and sum-factorised) and Cᵀ K C, checked
/// against the bilinear element's textbook matrices and against each other across the scalars.

#include "spaces/affine_element_matrices.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace iga {
namespace {

/// The 1D moments of the linear basis {1 − s, s} on [0, 1] (second derivatives vanish).
DerivativeMoments<LongDoubleMatrix> linear_moments() {
  DerivativeMoments<LongDoubleMatrix> m;
  for (auto& row : m.moment)
    for (auto& x : row) x.setZero(2, 2);
  m.moment[0][0] << 1.0L / 3, 1.0L / 6, 1.0L / 6, 1.0L / 3;  // ∫ N_a N_c
  m.moment[1][1] << 1, -1, -1, 1;                            // ∫ N_a' N_c'
  m.moment[0][1] << -0.5L, 0.5L, -0.5L, 0.5L;                // ∫ N_a N_c'
  m.moment[1][0] = m.moment[0][1].transpose();
  return m;
}

DerivativeMoments<DoubleDoubleMatrix> to_double_double(const DerivativeMoments<LongDoubleMatrix>& m) {
  DerivativeMoments<DoubleDoubleMatrix> d;
  for (int k = 0; k < 3; ++k)
    for (int l = 0; l < 3; ++l) d.moment[k][l] = DoubleDoubleMatrix::from_long_double(m.moment[k][l]);
  return d;
}

void put(LongDoubleMatrix& m, Eigen::Index i, Eigen::Index j, long double v) { m(i, j) = v; }
void put(DoubleDoubleMatrix& m, Eigen::Index i, Eigen::Index j, const DoubleDouble& v) { m.set(i, j, v); }

/// R(α, β) = X ⊗ Y of a tensor basis, for the general combination.
template <class Matrix, class Moments>
ReferenceIntegrals<Matrix> kronecker(const Moments& x, const Moments& y) {
  ReferenceIntegrals<Matrix> r;
  const auto product = [&](int alpha, int beta) {
    const auto& X = x.moment[kOrderXi[alpha]][kOrderXi[beta]];
    const auto& Y = y.moment[kOrderEta[alpha]][kOrderEta[beta]];
    const Eigen::Index nx = X.rows(), ny = Y.rows();
    Matrix m;
    m.resize(nx * ny, nx * ny);
    for (Eigen::Index j2 = 0; j2 < ny; ++j2)
      for (Eigen::Index i2 = 0; i2 < nx; ++i2)
        for (Eigen::Index j = 0; j < ny; ++j)
          for (Eigen::Index i = 0; i < nx; ++i) put(m, i + nx * j, i2 + nx * j2, X(i, i2) * Y(j, j2));
    return m;
  };
  r.mass = product(kValue, kValue);
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b) r.grad[a][b] = product(kDxi + a, kDxi + b);
  for (int p = 0; p < 3; ++p)
    for (int q = 0; q < 3; ++q) r.hess[p][q] = product(kDxixi + p, kDxixi + q);
  return r;
}

TEST(AffineElementMatrices, BilinearRectangleGivesTheTextbookMatrices) {
  // Q1 on an hx x hy rectangle: mass hx hy/36 (4, 2, 1), stiffness (hy/hx) X' ⊗ Y + (hx/hy) X ⊗ Y'.
  const double hx = 0.75, hy = 0.5;
  const Eigen::Matrix2d j = Eigen::Vector2d(hx, hy).asDiagonal();
  const DerivativeMoments<LongDoubleMatrix> m = linear_moments();
  LongDoubleMatrix mass, stiffness;
  tensor_form_matrix(m, m, affine_form_terms<long double>(BilinearForm::mass, j), mass);
  tensor_form_matrix(m, m, affine_form_terms<long double>(BilinearForm::laplace, j), stiffness);
  const long double area = 0.375L, rx = 0.5L / 0.75L, ry = 0.75L / 0.5L;
  EXPECT_NEAR(static_cast<double>(mass(0, 0) - area * 4 / 36), 0.0, 1e-18);
  EXPECT_NEAR(static_cast<double>(mass(0, 1) - area * 2 / 36), 0.0, 1e-18);
  EXPECT_NEAR(static_cast<double>(mass(0, 3) - area * 1 / 36), 0.0, 1e-18);
  EXPECT_NEAR(static_cast<double>(stiffness(0, 0) - (rx + ry) / 3), 0.0, 1e-18);
  EXPECT_NEAR(static_cast<double>(stiffness(0, 1) - (-rx / 3 + ry / 6)), 0.0, 1e-18);
  EXPECT_NEAR(static_cast<double>(stiffness(0, 3) - (-rx - ry) / 6), 0.0, 1e-18);
  // Constants are in the kernel of the stiffness matrix.
  EXPECT_LT(std::abs(static_cast<double>(stiffness.row(2).sum())), 1e-18);
}

TEST(AffineElementMatrices, WeightsOfTheUnitMapAreTheFormsCoefficients) {
  const Eigen::Matrix2d unit = Eigen::Matrix2d::Identity();
  const auto laplace = affine_form_terms<DoubleDouble>(BilinearForm::laplace, unit);
  ASSERT_EQ(laplace.size, 2);  // the off-diagonal metric is exactly zero and left out
  for (const auto& t : laplace) {
    EXPECT_EQ(t.alpha, t.beta);
    EXPECT_EQ(t.weight, DoubleDouble(1.0));
  }
  // D²u : D²v = u_ξξ v_ξξ + 2 u_ξη v_ξη + u_ηη v_ηη; Δu Δv adds the cross terms u_ξξ v_ηη.
  const auto hessian = affine_form_terms<DoubleDouble>(BilinearForm::hessian, unit);
  ASSERT_EQ(hessian.size, 3);
  EXPECT_EQ(hessian.term[1].alpha, kDxieta);
  EXPECT_EQ(hessian.term[1].weight, DoubleDouble(2.0));
  EXPECT_EQ(affine_form_terms<DoubleDouble>(BilinearForm::bilaplace, unit).size, 4);
  // long double keeps the Hessian's sixteen products apart: the mixed one appears twice.
  EXPECT_EQ(affine_form_terms<long double>(BilinearForm::hessian, unit).size, 4);
}

TEST(AffineElementMatrices, ScalarsAndPathsAgreeOnAShearedElement) {
  // Random moments of a 4-function 1D basis, a sheared element: the general combination of the
  // Kronecker reference integrals and the sum-factorised one, in long double and double-double,
  // then Cᵀ K C with a random sparse C, all agree to long double rounding.
  std::mt19937 gen(3);
  std::uniform_real_distribution<double> u(-1, 1);
  DerivativeMoments<LongDoubleMatrix> x;
  for (int k = 0; k < 3; ++k)
    for (int l = k; l < 3; ++l) {
      x.moment[k][l] = LongDoubleMatrix::NullaryExpr(4, 4, [&] { return static_cast<long double>(u(gen)); });
      if (k == l) x.moment[k][k] = (x.moment[k][k] + x.moment[k][k].transpose()).eval();
      else x.moment[l][k] = x.moment[k][l].transpose();
    }
  const DerivativeMoments<DoubleDoubleMatrix> xd = to_double_double(x);
  Eigen::Matrix2d j;
  j << 0.3, 0.07, -0.05, 0.2;
  Eigen::MatrixXd c = Eigen::MatrixXd::Zero(16, 9);
  for (int k = 0; k < 40; ++k) c(gen() % 16, gen() % 9) = u(gen);
  const ReferenceIntegrals<LongDoubleMatrix> r = kronecker<LongDoubleMatrix>(x, x);
  const ReferenceIntegrals<DoubleDoubleMatrix> rd = kronecker<DoubleDoubleMatrix>(xd, xd);
  for (BilinearForm form : {BilinearForm::mass, BilinearForm::laplace, BilinearForm::bilaplace, BilinearForm::hessian}) {
    LongDoubleMatrix general, tensor, local;
    DoubleDoubleMatrix general_dd, tensor_dd, local_dd;
    combine(affine_form_terms<long double>(form, j), r, general);
    tensor_form_matrix(x, x, affine_form_terms<long double>(form, j), tensor);
    combine(affine_form_terms<DoubleDouble>(form, j), rd, general_dd);
    tensor_form_matrix(xd, xd, affine_form_terms<DoubleDouble>(form, j), tensor_dd);
    const long double scale = general.cwiseAbs().maxCoeff();
    const double bound = 1e-16 * static_cast<double>(scale);  // ≈ 20 roundings of 2⁻⁶⁴
    for (Eigen::Index q = 0; q < 16; ++q)
      for (Eigen::Index p = 0; p < 16; ++p) {
        EXPECT_NEAR(static_cast<double>(tensor(p, q) - general(p, q)), 0.0, bound) << to_string(form);
        EXPECT_NEAR(static_cast<double>(general_dd(p, q).to_long_double() - general(p, q)), 0.0, bound);
        // The two double-double paths differ by double-double rounding only.
        EXPECT_LT(std::abs((tensor_dd(p, q) - general_dd(p, q)).hi), 1e-28 * static_cast<double>(scale));
      }
    symmetric_congruence(c, general, local);
    symmetric_congruence(c, general_dd, local_dd);
    const LongDoubleMatrix dense = c.cast<long double>().transpose() * general * c.cast<long double>();
    ASSERT_EQ(local.rows(), 9);
    for (Eigen::Index q = 0; q < 9; ++q)
      for (Eigen::Index p = 0; p < 9; ++p) {
        EXPECT_NEAR(static_cast<double>(local(p, q) - dense(p, q)), 0.0, bound * 10);
        EXPECT_NEAR(static_cast<double>(local_dd(p, q).to_long_double() - local(p, q)), 0.0, bound * 10);
        EXPECT_EQ(local_dd(p, q), local_dd(q, p));
      }
  }
}

}  // namespace
}  // namespace iga
