/// @file
/// Functionals of studies without an exact solution: point location by Newton's method on the
/// element maps, point values and integrals reproduced exactly for a function in the space, and
/// the Richardson order of a sequence with a known order.

#include "solver/study_functionals.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/support/test_support.hpp"

namespace iga {
namespace {

TEST(StudyFunctionals, LocatesPointsOnCurvedAndTriangularElements) {
  for (const char* yaml : {"domain: {type: quarter_annulus, inner: 1, outer: 2}\nspace: {type: bspline, degree: 2, elements: [3, 2]}\n",
                           "domain: {type: unit_square}\nspace: {type: ws4, elements: 2}\n"}) {
    const SpacePtr space = test::space_from_yaml(yaml);
    const std::unique_ptr<Space::Evaluator> evaluator = space->make_evaluator();
    const PointLocator locator(space);
    QuadratureRule probe;
    probe.points = {{0.3, 0.2}};
    probe.weights = {0.0};
    PointValues geometry;
    for (int e = 0; e < space->num_elements(); e += std::max(1, space->num_elements() / 5)) {
      evaluator->evaluate_geometry(e, probe, geometry);
      const Point2 x = geometry.x.col(0);
      const auto at = locator.locate(x);
      ASSERT_TRUE(at.has_value()) << yaml << " element " << e;
      // Found again: the same physical point (possibly in a neighbour sharing it).
      QuadratureRule back;
      back.points = {at->reference};
      back.weights = {0.0};
      evaluator->evaluate_geometry(at->element, back, geometry);
      EXPECT_LT((geometry.x.col(0) - x).norm(), 1e-10);
    }
    EXPECT_FALSE(locator.locate(Point2(5.0, 5.0)).has_value());
  }
}

TEST(StudyFunctionals, PointValueAndIntegralOfAConstant) {
  // B-splines sum to one: coefficients all 2 give u = 2, its mean over [0,2] x [0,1] is 4.
  const SpacePtr space = test::space_from_yaml(
      "domain: {type: rectangle, min: [0, 0], max: [2, 1]}\nspace: {type: bspline, degree: 3, elements: [3, 2]}\n");
  const std::vector<FunctionalSpec> f = {{"p", FunctionalSpec::Kind::point, Point2(1.3, 0.7)},
                                         {"i", FunctionalSpec::Kind::integral, Point2::Zero()}};
  const std::vector<double> v = evaluate_functionals(f, *space, Eigen::VectorXd::Constant(space->dimension(), 2.0));
  EXPECT_NEAR(v[0], 2.0, 1e-13);
  EXPECT_NEAR(v[1], 4.0, 1e-13);
}

TEST(StudyFunctionals, RichardsonOrderOfAKnownSequence) {
  // F_l = 1 + 3 h_l^4 with h halving: order 4 from the third value on.
  std::vector<double> h, F;
  for (int l = 0; l < 5; ++l) h.push_back(std::pow(0.5, l)), F.push_back(1 + 3 * std::pow(h.back(), 4));
  EXPECT_FALSE(richardson_order(F, h, 1).has_value());
  for (std::size_t l = 2; l < 5; ++l) EXPECT_NEAR(*richardson_order(F, h, l), 4.0, 1e-9);
}

}  // namespace
}  // namespace iga
