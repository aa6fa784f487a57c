// The piece-by-piece evaluation of one WS4 function and of load vectors (ws4_evaluator.hpp)
// against the tabulated path: all active functions from Evaluator::evaluate, contracted after.

#include "spaces/ws4/ws4_space.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <random>

#include "spaces/ws4/ws4_basis.hpp"
#include "spaces/ws4/ws4_piece_table.hpp"
#include "spaces/ws4/ws4_split.hpp"
#include "tests/spaces/ws4/ws4_test_meshes.hpp"
#include "tests/support/test_support.hpp"

namespace iga::ws4 {
namespace {

using test::perturbed_square;

using test::random_vector;

/// A rule whose points lie on split lines, vertices and element edges as well as inside regions
/// (the one-sided pieces of Ws4Split::locate), in no particular order.
QuadratureRule scattered_points() {
  QuadratureRule r;
  const Ws4Split& split = Ws4Split::reference();
  for (int v = 0; v < static_cast<int>(split.vertices().size()); v += 7) r.points.push_back(split.vertex_point(v));
  std::mt19937 gen(5);
  std::uniform_real_distribution<double> u(0, 1);
  for (int k = 0; k < 40; ++k) {
    const double a = u(gen), b = u(gen) * (1 - a);
    r.points.emplace_back(a, b);
  }
  r.points.emplace_back(0.5, 0.0);
  r.points.emplace_back(0.25, 0.75);
  r.weights.assign(r.points.size(), 0.01);
  return r;
}

/// max |a - b| / max |b|.
double relative_difference(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  return (a - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff();
}

TEST(Ws4Evaluator, FunctionValuesMatchTheTabulatedBasis) {
  const Ws4Space space(perturbed_square(3, 17));
  const Eigen::VectorXd coef = random_vector(space.dimension(), 3);
  const auto evaluator = space.make_evaluator();
  const unsigned flags = update_values | update_gradients | update_hessians;
  const QuadratureRule scattered = scattered_points();
  double worst[6] = {};
  for (const QuadratureRule* rule : {space.quadrature(0, 6).get(), &scattered}) {
    for (int e = 0; e < space.num_elements(); ++e) {
      PointValues all, geometry;
      FunctionValues uh;
      evaluator->evaluate(e, *rule, flags, all);
      evaluator->evaluate_function(e, *rule, coef, flags, geometry, uh);
      ASSERT_EQ(geometry.dofs, all.dofs);
      ASSERT_EQ(geometry.jacobian.size(), all.jacobian.size());
      EXPECT_LT((geometry.x - all.x).cwiseAbs().maxCoeff(), 1e-15);
      EXPECT_LT((geometry.jacobian[0] - all.jacobian[0]).cwiseAbs().maxCoeff(), 1e-15);
      Eigen::VectorXd c(all.num_functions());
      for (int i = 0; i < c.size(); ++i) c(i) = coef(all.dofs[i]);
      const Eigen::MatrixXd* tables[6] = {&all.value, &all.dx, &all.dy, &all.dxx, &all.dxy, &all.dyy};
      const Eigen::VectorXd* got[6] = {&uh.value, &uh.dx, &uh.dy, &uh.dxx, &uh.dxy, &uh.dyy};
      for (int a = 0; a < 6; ++a) {
        const Eigen::VectorXd want = tables[a]->transpose() * c;
        ASSERT_EQ(got[a]->size(), want.size());
        worst[a] = std::max(worst[a], relative_difference(*got[a], want));
      }
    }
  }
  // Both routes sum the same pieces in another order: round-off relative to the function's size
  // (derivatives scale with 1/h^k, the pieces' coefficients with up to 1e3 on the smallest regions).
  std::cout << "piecewise vs tabulated, relative differences:";
  for (double w : worst) std::cout << " " << w;
  std::cout << "\n";
  for (int a = 0; a < 6; ++a) EXPECT_LT(worst[a], 1e-12) << "array " << a;
}

TEST(Ws4Evaluator, LoadVectorMatchesTheTabulatedBasis) {
  const Ws4Space space(perturbed_square(3, 29));
  const auto evaluator = space.make_evaluator();
  const QuadratureRule scattered = scattered_points();
  for (const QuadratureRule* rule : {space.quadrature(0, 9).get(), &scattered}) {
    const Eigen::VectorXd w = random_vector(rule->size(), 11);
    for (int e = 0; e < space.num_elements(); ++e) {
      PointValues all, geometry;
      evaluator->evaluate(e, *rule, update_values, all);
      evaluator->evaluate_geometry(e, *rule, geometry);
      EXPECT_EQ(geometry.dofs, all.dofs);
      Eigen::VectorXd local;
      evaluator->integrate_values(e, *rule, geometry, w, local);
      const Eigen::VectorXd want = all.value * w;
      ASSERT_EQ(local.size(), want.size());
      EXPECT_LT(relative_difference(local, want), 1e-12) << "element " << e;
    }
  }
}

TEST(Ws4Evaluator, PieceTableHoldsEveryNonzeroPieceOncePerOrbit) {
  // Every region's listed functions have, in its representative's coordinates ξ = L⁻¹ (x - c),
  // the representative's pieces: piece(r, function[j])(L ξ) = stored piece j (ξ). Both are
  // computed separately (in long double, then rounded), and L has integer entries: they agree to
  // a few units of the last place of the largest term, checked at points of the size of the
  // regions (|ξ| <= 0.2). Every function left out is zero on the region, and the representatives
  // are at most a third of the regions (orbits of six, three or one).
  const Ws4Basis& basis = Ws4Basis::reference();
  const Ws4PieceTable& t = Ws4PieceTable::reference();
  ASSERT_EQ(t.num_regions(), static_cast<int>(basis.split().regions().size()));
  int representatives = 0;
  const Point2 samples[4] = {Point2(0.0, 0.0), Point2(0.2, -0.1), Point2(-0.13, 0.17), Point2(0.05, 0.2)};
  for (int r = 0; r < t.num_regions(); ++r) {
    const int r0 = t.representative[r];
    ASSERT_EQ(t.representative[r0], r0);
    representatives += r0 == r;
    ASSERT_EQ(t.width(r) % 4, 0);
    ASSERT_GE(t.width(r), t.active(r));
    ASSERT_LE(t.width(r), t.max_width);
    const Eigen::Matrix2d linv = t.inverse_linear[r];
    EXPECT_EQ(std::abs(linv.determinant()), 1.0);
    const Eigen::Matrix2d l = linv.inverse();
    std::vector<bool> listed(Ws4Basis::size, false);
    const double* block = t.by_monomial.data() + static_cast<size_t>(t.block_begin[r]) * Ws4PieceTable::monomials;
    for (int j = 0; j < t.active(r); ++j) {
      const int i = t.function[t.begin[r] + j];
      ASSERT_FALSE(listed[i]);
      listed[i] = true;
      const double* f = t.by_function.data() + static_cast<size_t>(t.piece_begin[r] + j) * Ws4PieceTable::padded;
      EXPECT_EQ(f[Ws4PieceTable::padded - 1], 0.0);
      Poly4 stored;
      double scale = 0;
      for (int a = 0; a <= Poly4::max_degree; ++a)
        for (int b = 0; a + b <= Poly4::max_degree; ++b) {
          stored.coefficient(a, b) = f[Poly4::index(a, b)];
          scale += std::abs(f[Poly4::index(a, b)]);
          EXPECT_EQ(block[Poly4::index(a, b) * t.width(r) + j], f[Poly4::index(a, b)]);
        }
      for (const Point2& xi : samples)
        EXPECT_NEAR(basis.piece(r, i)(Point2(l * xi)), stored(xi), 1e-14 * scale) << "region " << r << " function " << i;
    }
    for (int j = t.active(r); j < t.width(r); ++j)
      for (int m = 0; m < Ws4PieceTable::monomials; ++m) EXPECT_EQ(block[m * t.width(r) + j], 0.0);
    for (int i = 0; i < Ws4Basis::size; ++i)
      if (!listed[i]) EXPECT_TRUE(basis.piece(r, i).is_zero()) << "region " << r << " function " << i;
  }
  EXPECT_LE(3 * representatives, t.num_regions());
}

TEST(Ws4Evaluator, EveryFlagSetAndRunLengthMatchesTheTabulatedBasis) {
  // Values alone, with gradients, with Hessians; rules whose runs (points of one region in a row)
  // hold 3 or 6 and 7 or 14 points (remainders of the loops over 8 and 4 points), and the
  // scattered rule (runs of one point, regions met again later, more than one block of regions).
  const Ws4Space space(perturbed_square(2, 41));
  const Eigen::VectorXd coef = random_vector(space.dimension(), 7);
  const auto evaluator = space.make_evaluator();
  const QuadratureRule scattered = scattered_points();
  const unsigned flag_sets[3] = {update_values, update_values | update_gradients,
                                 update_values | update_gradients | update_hessians};
  for (const QuadratureRule* rule : {space.quadrature(0, 2).get(), space.quadrature(0, 5).get(), &scattered})
    for (const unsigned flags : flag_sets)
      for (int e = 0; e < space.num_elements(); ++e) {
        PointValues all, geometry;
        FunctionValues uh;
        evaluator->evaluate(e, *rule, flags, all);
        evaluator->evaluate_function(e, *rule, coef, flags, geometry, uh);
        Eigen::VectorXd c(all.num_functions());
        for (int i = 0; i < c.size(); ++i) c(i) = coef(all.dofs[i]);
        const Eigen::MatrixXd* tables[6] = {&all.value, &all.dx, &all.dy, &all.dxx, &all.dxy, &all.dyy};
        const Eigen::VectorXd* got[6] = {&uh.value, &uh.dx, &uh.dy, &uh.dxx, &uh.dxy, &uh.dyy};
        const int arrays = (flags & update_hessians) ? 6 : (flags & update_gradients) ? 3 : 1;
        for (int a = 0; a < arrays; ++a) {
          const Eigen::VectorXd want = tables[a]->transpose() * c;
          ASSERT_EQ(got[a]->size(), want.size());
          // The bound of FunctionValuesMatchTheTabulatedBasis: the same sums in another order.
          EXPECT_LT(relative_difference(*got[a], want), 1e-12) << "array " << a << " element " << e;
        }
      }
}

TEST(Ws4Evaluator, GeometryIsTheAffineMapAtEveryPoint) {
  // x = p0 + J ξ at each point (one rounding per product and sum: a few units of the last place of
  // the coordinates, which are at most 1 here), and the same Jacobian J, exactly, at every point.
  const Ws4Space space(perturbed_square(2, 43));
  const auto evaluator = space.make_evaluator();
  const QuadratureRule scattered = scattered_points();
  for (const QuadratureRule* rule : {space.quadrature(0, 4).get(), &scattered})
    for (int e = 0; e < space.num_elements(); ++e) {
      PointValues geometry;
      evaluator->evaluate_geometry(e, *rule, geometry);
      const Eigen::Matrix2d j = space.jacobian(e);
      const Point2 p0 = space.mesh().vertices()[space.mesh().triangle(e)[0]];
      ASSERT_EQ(geometry.num_points(), rule->size());
      ASSERT_EQ(static_cast<int>(geometry.jacobian.size()), rule->size());
      for (int k = 0; k < rule->size(); ++k) {
        EXPECT_EQ(geometry.jacobian[k], j) << "point " << k;
        EXPECT_LT((geometry.x.col(k) - (p0 + j * rule->points[k])).cwiseAbs().maxCoeff(), 1e-15);
      }
    }
}

TEST(Ws4Evaluator, NonFiniteDataReachTheLoadVector) {
  const Ws4Space space(perturbed_square(2, 31));
  const auto evaluator = space.make_evaluator();
  const RulePtr rule = space.quadrature(0, 4);
  Eigen::VectorXd w = Eigen::VectorXd::Ones(rule->size());
  w(rule->size() / 2) = std::nan("");
  PointValues geometry;
  evaluator->evaluate_geometry(0, *rule, geometry);
  Eigen::VectorXd local;
  evaluator->integrate_values(0, *rule, geometry, w, local);
  EXPECT_FALSE(local.allFinite());
}

TEST(Ws4Evaluator, HigherDerivativesAreRefused) {
  const Ws4Space space(perturbed_square(1, 1));
  const auto evaluator = space.make_evaluator();
  PointValues geometry;
  FunctionValues uh;
  EXPECT_THROW(evaluator->evaluate_function(0, *space.quadrature(0, 2), Eigen::VectorXd::Zero(space.dimension()),
                                            update_bilaplacian, geometry, uh),
               std::logic_error);
}

}  // namespace
}  // namespace iga::ws4
