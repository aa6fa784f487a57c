/// @file
/// Closed-form WS4 element matrices: the reference numbers of the WS4 notes §9, and equality with
/// the quadrature-based element matrices of assembly/integrators on perturbed triangles.

#include "spaces/closed_forms.hpp"
#include "spaces/ws4/ws4_reference_matrices.hpp"

#include <gtest/gtest.h>

#include <random>

#include "assembly/integrators.hpp"
#include "spaces/element_values.hpp"
#include "spaces/ws4/ws4_space.hpp"

namespace iga::ws4 {
namespace {

TEST(Ws4Matrices, ReferenceNumbersOfTheNotes) {
  const ReferenceIntegrals<Eigen::MatrixXd>& r = ws4_reference_integrals();
  const Eigen::MatrixXd lap = r.grad[0][0] + r.grad[1][1];
  EXPECT_NEAR(lap(0, 0), 4.0 / 7, 1e-13);
  EXPECT_NEAR(r.mass(0, 0), 1.0 / 1440, 1e-16);
  EXPECT_NEAR(r.hess[0][0](0, 0), 76.8, 1e-10);
  EXPECT_NEAR(r.mass.sum(), 0.5, 1e-14);
  // Σ_i B_i = 1: every derivative matrix annihilates constants. Computed in long double and rounded
  // once, to round-off of the entries (in double: 3.6e-15 and 1.1e-15 relative).
  EXPECT_LT(lap.rowwise().sum().cwiseAbs().maxCoeff(), 1e-15);
  for (int p = 0; p < 3; ++p)
    for (int q = 0; q < 3; ++q)
      EXPECT_LT(r.hess[p][q].rowwise().sum().cwiseAbs().maxCoeff(), 1e-15 * r.hess[p][q].cwiseAbs().maxCoeff())
          << p << q;
  const int index[11] = {1, 4, 10, 16, 19, 25, 31, 34, 40, 46, 49};
  const double diag[11] = {0.5714285714, 0.6642857143, 0.7327380952, 0.7238095238, 1.016402116, 0.7285714286,
                           1.832569444,  0.7852040816, 0.09789115646, 0.1222633929, 0.3781409439};
  for (int k = 0; k < 11; ++k) EXPECT_NEAR(lap(index[k] - 1, index[k] - 1), diag[k], 1e-9) << "B" << index[k];
}

TEST(Ws4Matrices, ClosedFormEqualsQuadratureOnPerturbedTriangles) {
  Triangulation mesh = Triangulation::rectangle(2, 2, Point2(0, 0), Point2(1, 1));
  mesh.move_vertex(4, Point2(0.57, 0.43));  // the centre vertex: all 8 triangles distorted
  const Ws4Space space(mesh);
  for (BilinearForm form : {BilinearForm::mass, BilinearForm::laplace, BilinearForm::bilaplace, BilinearForm::hessian}) {
    ElementValues ev(space, Form(form)->flags());
    for (int t = 0; t < space.num_elements(); ++t) {
      Eigen::MatrixXd closed, quad;
      ASSERT_TRUE(space.closed_forms()->element_matrix(t, form, closed));
      ev.reinit(t, *space.quadrature(t, 8));
      Form(form)->element_matrix(ev, quad);
      EXPECT_LT((closed - quad).cwiseAbs().maxCoeff(), 1e-11 * quad.cwiseAbs().maxCoeff())
          << "form " << static_cast<int>(form) << " element " << t;
    }
  }
}


TEST(Ws4Matrices, DoubleDoubleReferenceMatricesAnnihilateConstantsBeyondLongDouble) {
  // Σ_i B_i = 1: the row sums of every derivative matrix vanish exactly. Long double sums leave
  // ≈ 1e-19 of the entries; the double-double ones must be far below (here: 1e-25 relative).
  const ReferenceIntegrals<DoubleDoubleMatrix>& r = ws4_reference_integrals_double_double(BilinearForm::hessian);
  for (int p = 0; p < 3; ++p)
    for (int q = 0; q < 3; ++q) {
      const DoubleDoubleMatrix& m = r.hess[p][q];
      for (int i = 0; i < m.rows(); ++i) {
        DoubleDouble sum(0.0);
        for (int j = 0; j < m.cols(); ++j) sum += m(i, j);
        EXPECT_LT(std::abs(sum.hi), 1e-25 * m.hi.cwiseAbs().maxCoeff()) << p << q << " row " << i;
      }
    }
  // And they agree with the long double ones to those ones' accuracy.
  const ReferenceIntegrals<LongDoubleMatrix>& e = ws4_reference_integrals_extended();
  for (int i = 0; i < 51; ++i)
    for (int j = 0; j < 51; ++j)
      EXPECT_NEAR(static_cast<double>(e.hess[0][0](i, j) - r.hess[0][0](i, j).to_long_double()), 0.0,
                  1e-16 * r.hess[0][0].hi.cwiseAbs().maxCoeff());
}

TEST(Ws4Matrices, DoubleDoubleTablesLeaveLongDoubleArithmeticWorking) {
  // The double-double tables are pure SSE code, but a compiler may route a 64-bit move through an
  // MMX register, which fills the x87 register stack unless followed by EMMS: every long double
  // load after it then gives NaN (seen as NaN long double element matrices in the next test).
  // Whether that happens depends on the compiler's register allocation, so this guards the build
  // flag (-mno-mmx) rather than a line of code.
  ws4_reference_integrals_double_double(BilinearForm::hessian);
  volatile long double one = 1;
  const long double sum = one + one + one + one + one + one + one + one + one;
  EXPECT_EQ(sum, 9.0L);
  const ReferenceIntegrals<LongDoubleMatrix>& e = ws4_reference_integrals_extended();
  EXPECT_TRUE(e.hess[0][0].allFinite());
}

TEST(Ws4Matrices, DoubleDoubleElementMatricesEqualTheLongDoubleOnes) {
  Triangulation mesh = Triangulation::rectangle(2, 2, Point2(0, 0), Point2(1, 1));
  mesh.move_vertex(4, Point2(0.57, 0.43));
  const Ws4Space space(mesh);
  for (BilinearForm form : {BilinearForm::mass, BilinearForm::laplace, BilinearForm::bilaplace, BilinearForm::hessian})
    for (int t = 0; t < space.num_elements(); ++t) {
      Eigen::Matrix<long double, Eigen::Dynamic, Eigen::Dynamic> extended;
      DoubleDoubleMatrix dd;
      ASSERT_TRUE(space.closed_forms()->element_matrix(t, form, extended));
      ASSERT_TRUE(space.closed_forms()->element_matrix(t, form, dd));
      const double scale = static_cast<double>(extended.cwiseAbs().maxCoeff());
      for (int i = 0; i < 51; ++i)
        for (int j = 0; j < 51; ++j) {
          EXPECT_EQ(dd(i, j), dd(j, i));
          EXPECT_LT(std::abs(static_cast<double>(extended(i, j) - dd(i, j).to_long_double())), 1e-13 * scale)
              << "form " << static_cast<int>(form) << " element " << t;
        }
    }
}

}  // namespace
}  // namespace iga::ws4
