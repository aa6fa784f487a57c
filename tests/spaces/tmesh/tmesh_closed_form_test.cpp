// TMeshSpace's element matrices as Kronecker products of side integrals against the quadrature
// path (tensor Gauss rule of the assembly, ElementValues and the extended integrator).
#include <gtest/gtest.h>

#include <iostream>
#include <numbers>

#include "assembly/integrators.hpp"
#include "spaces/closed_forms.hpp"
#include "spaces/element_values.hpp"
#include "spaces/tmesh/tmesh_space.hpp"
#include "tests/support/test_support.hpp"

using namespace iga;

namespace {

/// A dyadic hierarchical T-mesh (T-junctions, three cell sizes) on a non-square rectangle.
std::string yaml(const std::string& section, int n, int r) {
  return "domain: {type: rectangle, min: [0, 0], max: [3.0, 2.0]}\n"
         "space: {type: tmesh, section: " + section + ", n: " + std::to_string(n) + ", regularity: " + std::to_string(r) +
         ", frequency: 1, elements: [3, 2], refine: [[0, 0, 1.5, 1.0], [0.75, 0.5, 1.5, 1.0]]}\n";
}

TEST(TMeshClosedForm, MatchesTheQuadratureMatrices) {
  for (const auto& [section, n, r] : {std::tuple{"trig", 3, 1}, std::tuple{"poly", 4, 1}, std::tuple{"hyperbolic", 5, 2}}) {
    const SpacePtr s = test::space_from_yaml(yaml(section, n, r));
    const auto& space = dynamic_cast<const TMeshSpace&>(*s);
    ASSERT_GT(space.num_elements(), 6);
    for (BilinearForm form : {BilinearForm::mass, BilinearForm::laplace, BilinearForm::bilaplace, BilinearForm::hessian}) {
      ElementValues ev(space, update_values | update_gradients | update_hessians);
      double worst = 0.0;
      for (int e = 0; e < space.num_elements(); ++e) {
        ev.reinit(e, *space.quadrature(e, 2 * space.degree() + 1));
        MatrixXld quadrature, closed;
        Form(form)->element_matrix(ev, quadrature);
        ASSERT_TRUE(space.closed_forms()->element_matrix(e, form, closed));
        ASSERT_EQ(closed.rows(), quadrature.rows());
        ASSERT_EQ(closed.cols(), quadrature.cols());
        const long double scale = quadrature.cwiseAbs().maxCoeff();
        worst = std::max(worst, static_cast<double>((closed - quadrature).cwiseAbs().maxCoeff() / scale));
        Eigen::MatrixXd closed_double;
        ASSERT_TRUE(space.closed_forms()->element_matrix(e, form, closed_double));
        EXPECT_LT((closed_double - closed.cast<double>()).cwiseAbs().maxCoeff(), 1e-15 * static_cast<double>(scale));
      }
      std::cout << section << " n=" << n << " form " << static_cast<int>(form) << ": max relative difference " << worst
                << "\n";
      // The same sums in another order (separated, accumulated in long double), from the same
      // double tables: round-off of double products.
      EXPECT_LT(worst, 1e-13);
    }
  }
}

TEST(TMeshClosedForm, DoubleDoubleMatchesTheQuadratureAndLongDoubleMatrices) {
  for (const auto& [section, n, r] : {std::tuple{"trig", 3, 1}, std::tuple{"poly", 3, 1}, std::tuple{"hyperbolic", 5, 2}}) {
    const SpacePtr s = test::space_from_yaml(yaml(section, n, r));
    const auto& space = dynamic_cast<const TMeshSpace&>(*s);
    for (BilinearForm form : {BilinearForm::mass, BilinearForm::laplace, BilinearForm::bilaplace, BilinearForm::hessian}) {
      ElementValues ev(space, update_values | update_gradients | update_hessians);
      double worst_quadrature = 0.0, worst_long_double = 0.0;
      for (int e = 0; e < space.num_elements(); ++e) {
        ev.reinit(e, *space.quadrature(e, 2 * space.degree() + 1));
        DoubleDoubleMatrix quadrature, closed;
        Form(form)->element_matrix(ev, quadrature);
        ASSERT_TRUE(space.closed_forms()->element_matrix(e, form, closed));
        MatrixXld extended;
        ASSERT_TRUE(space.closed_forms()->element_matrix(e, form, extended));
        ASSERT_EQ(closed.rows(), quadrature.rows());
        ASSERT_EQ(closed.cols(), quadrature.cols());
        const long double scale = extended.cwiseAbs().maxCoeff();
        for (Eigen::Index j = 0; j < closed.cols(); ++j)
          for (Eigen::Index i = 0; i < closed.rows(); ++i) {
            ASSERT_EQ(closed(i, j), closed(j, i));  // one triangle computed, mirrored
            const DoubleDouble c = closed(i, j);
            worst_quadrature = std::max(worst_quadrature, std::abs((c - quadrature(i, j)).hi) / static_cast<double>(scale));
            worst_long_double = std::max(
                worst_long_double, static_cast<double>(std::abs(c.to_long_double() - extended(i, j)) / scale));
          }
      }
      std::cout << section << " n=" << n << " form " << static_cast<int>(form) << ": max relative difference "
                << worst_quadrature << " to quadrature, " << worst_long_double << " to long double\n";
      // The same products of double tables summed in another order; the quadrature path also rounds
      // the pushed-forward derivatives (divided by the cell size) to double.
      EXPECT_LT(worst_quadrature, 1e-13);
      // Long double sums of up to a few hundred terms: their rounding, far below double's.
      EXPECT_LT(worst_long_double, 1e-16);
    }
  }
}

TEST(TMeshClosedForm, FineCellsNeedFewerExtraPointsAndStayExact) {
  // The extra degree of non-polynomial rules follows the largest w h: the smallest even e with
  // (w h)^(e+1) / (e+1)! <= 1e-17, 16 at most, none for polynomial sections.
  EXPECT_EQ(non_polynomial_extra_degree(0.0), 0);
  EXPECT_EQ(non_polynomial_extra_degree(std::numbers::pi / 2), 16);
  EXPECT_EQ(non_polynomial_extra_degree(std::numbers::pi / 128), 8);
  for (double wh = 1e-4; wh < 4.0; wh *= 1.3) {
    const int e = non_polynomial_extra_degree(wh);
    double bound = 1.0;
    for (int k = 1; k <= e + 1; ++k) bound *= wh / k;
    if (e < 16) EXPECT_LE(bound, 1e-17) << "w h = " << wh;
    EXPECT_GE(e, non_polynomial_extra_degree(wh / 1.3));
  }
  // On a fine trigonometric mesh the shorter rule still gives the closed-form matrices (whose
  // side integrals keep the full rule) to round-off.
  const std::string fine = "domain: {type: rectangle, min: [0, 0], max: [3.0, 2.0]}\n"
                           "space: {type: tmesh, section: trig, n: 3, regularity: 1, frequency: 1, elements: [48, 32]}\n";
  const SpacePtr s = test::space_from_yaml(fine);
  const auto& space = dynamic_cast<const TMeshSpace&>(*s);
  const int degree = 2 * space.degree() + 1;
  EXPECT_LT(space.quadrature(0, degree)->size(), tensor_gauss(degree + 16).size());
  ElementValues ev(space, update_values | update_gradients | update_hessians);
  for (BilinearForm form : {BilinearForm::mass, BilinearForm::bilaplace}) {
    double worst = 0.0;
    for (int e = 0; e < space.num_elements(); e += 97) {
      ev.reinit(e, *space.quadrature(e, degree));
      MatrixXld quadrature, closed;
      Form(form)->element_matrix(ev, quadrature);
      ASSERT_TRUE(space.closed_forms()->element_matrix(e, form, closed));
      worst = std::max(worst, static_cast<double>((closed - quadrature).cwiseAbs().maxCoeff() / quadrature.cwiseAbs().maxCoeff()));
    }
    EXPECT_LT(worst, 1e-13) << "form " << static_cast<int>(form);
  }
}

}  // namespace
