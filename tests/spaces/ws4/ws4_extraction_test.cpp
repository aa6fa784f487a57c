/// @file
/// The exact WS4 extraction C_K = A⁻¹ T_K (notes §8.2–8.3): the 1D edge-trace maps of App. B on a
/// basis of each univariate spline space, the exact inverse of the collocation matrix against the
/// rationals of App. A, T_K G_K = A on a perturbed mesh (T_K alone, without any inverse), and
/// agreement with the old route C_K = G_K⁻¹ (LU of the functional matrix, kept here only).

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <cmath>
#include <functional>
#include <iostream>

#include "spaces/ws4/ws4_collocation.hpp"
#include "spaces/ws4/ws4_edge_traces.hpp"
#include "spaces/ws4/ws4_hermite_transform.hpp"
#include "spaces/ws4/ws4_jitter.hpp"
#include "spaces/ws4/ws4_space.hpp"

namespace iga::ws4 {
namespace {

/// d^j/ds^j of (s − c)_+^p (c = 0 gives the monomial s^p on [0, 1]).
double truncated_power(double s, double c, int p, int j) {
  if (j > p) return 0.0;
  if (s < c || (s == c && p - j > 0)) return 0.0;
  double f = 1.0;
  for (int k = 0; k < j; ++k) f *= p - k;
  return f * std::pow(s - c, p - j);
}

TEST(Ws4Extraction, EdgeTraceMapsAreExactOnEachUnivariateSplineSpace) {
  // Trace m is a spline of degree 4 − m, C^{3 − m} at ¼, ½, ¾: monomials s^0 … s^{4−m} and the
  // truncated powers (s − c)_+^{4−m} span it (dimension 5 − m + 3).
  double worst = 0.0;
  int checked = 0;
  for (int m = 0; m <= 2; ++m) {
    const int p = 4 - m;
    std::vector<std::pair<double, int>> basis;  // (c, degree)
    for (int k = 0; k <= p; ++k) basis.push_back({0.0, k});
    for (double c : {0.25, 0.5, 0.75}) basis.push_back({c, p});
    const EdgeTraceData& layout = edge_trace_data(m);
    EXPECT_EQ(layout.size(), static_cast<int>(basis.size())) << m;
    for (const auto& [c, degree] : basis) {
      std::vector<double> data;
      for (double end : {0.0, 1.0})
        for (int i = 0; i < layout.end_derivatives; ++i) data.push_back(truncated_power(end, c, degree, i));
      for (double s : layout.interior_s) data.push_back(truncated_power(s, c, degree, 0));
      for (int j = 1; m + j <= 3; ++j)
        for (double s : {0.25, 0.5, 0.75}) {
          // Only what the functionals use: g₀′ at ½, g₀″ and g₁′ at ¼ and ¾.
          if ((m == 0 && j == 1 && s != 0.5) || (m == 0 && j == 2 && s == 0.5) || (m == 1 && j == 1 && s == 0.5))
            continue;
          const std::vector<long double>& map = edge_trace_map(m, j, s);
          long double got = 0;
          for (size_t k = 0; k < data.size(); ++k) got += map[k] * data[k];
          // At a breakpoint the j-th derivative is continuous (j <= 3 − m), so either side will do.
          worst = std::max(worst, std::abs(static_cast<double>(got) - truncated_power(s, c, degree, j)));
          ++checked;
        }
    }
  }
  std::cout << checked << " trace derivatives, worst error " << worst << "\n";
  EXPECT_EQ(checked, 8 * 6 + 7 * 5 + 6 * 3);
  EXPECT_LT(worst, 1e-12);
  EXPECT_THROW(edge_trace_map(0, 4, 0.5), std::logic_error);
}

TEST(Ws4Extraction, CollocationInverseIsExact) {
  const Matrix51L& inverse = ws4_coefficients_from_functionals();
  Matrix51L a = Matrix51L::Zero();  // A from the exact table, each entry rounded to long double
  for (int i = 0; i < 51; ++i)
    for (const CollocationEntry& e : ws4_collocation_table()[i])
      a(e.j - 1, i) = static_cast<long double>(e.numerator) / static_cast<long double>(e.denominator);
  const Matrix51L product = inverse * a;
  const double deviation =
      static_cast<double>((product - Matrix51L::Identity()).cwiseAbs().maxCoeff());
  std::cout << "|A^-1 A - I|_max = " << deviation << "\n";
  EXPECT_LT(deviation, 1e-17);
  // Rows of App. A: b4 = ρ1 + ρ4/16, b10 = ρ1 + 3ρ4/16 + ρ10/96, and three entries of b49.
  auto entry = [&](int b, int r) { return static_cast<double>(inverse(b - 1, r - 1)); };
  EXPECT_DOUBLE_EQ(entry(4, 1), 1.0);
  EXPECT_DOUBLE_EQ(entry(4, 4), 1.0 / 16);
  EXPECT_EQ((inverse.row(3).array() != 0).count(), 2);
  EXPECT_DOUBLE_EQ(entry(10, 4), 3.0 / 16);
  EXPECT_DOUBLE_EQ(entry(10, 10), 1.0 / 96);
  EXPECT_DOUBLE_EQ(entry(49, 49), 14604.0 / 7375);
  EXPECT_DOUBLE_EQ(entry(49, 1), 2882177.0 / 9440000);
  EXPECT_DOUBLE_EQ(entry(49, 46), 86629.0 / 226560000);
  // Partition of unity: the spline with ρ(1) (ones at ρ1–3, ρ49–51) has all b_i = 1.
  Eigen::Matrix<long double, 51, 1> rho_one = Eigen::Matrix<long double, 51, 1>::Zero();
  for (int j : {0, 1, 2, 48, 49, 50}) rho_one(j) = 1;
  EXPECT_LT(static_cast<double>(((inverse * rho_one).array() - 1.0L).abs().maxCoeff()), 1e-17);
}

/// A 4 x 4 unit-square mesh with jittered interior vertices: boundary frames, both edge orientations.
Ws4Space perturbed_space() {
  Triangulation mesh = Triangulation::rectangle(4, 4, Point2(0, 0), Point2(1, 1));
  jitter_interior_vertices(mesh, 0.2, 11);
  return Ws4Space(std::move(mesh));
}

TEST(Ws4Extraction, FunctionalTransformTimesFunctionalMatrixIsTheCollocationMatrix) {
  // ρ_j(B_i) = Σ_m T_K(j, m) g_m(B_i): T_K G_K = A for every element, whatever its shape, frames
  // and edge orientations. A has entries up to 5124.
  const Ws4Space space = perturbed_space();
  const Eigen::MatrixXd a = ws4_collocation_matrix();
  double worst = 0.0;
  for (int t = 0; t < space.num_elements(); ++t) {
    const Eigen::MatrixXd t_k = ws4_functionals_from_dofs(space.dof_geometry(t)).cast<double>();
    const Eigen::MatrixXd ta = t_k * space.element_functionals(t);
    worst = std::max(worst, (ta - a).cwiseAbs().maxCoeff() / a.cwiseAbs().maxCoeff());
  }
  std::cout << "max |T_K G_K - A| / max |A| over " << space.num_elements() << " elements: " << worst << "\n";
  EXPECT_LT(worst, 1e-13);
}

TEST(Ws4Extraction, ExactExtractionAgreesWithTheInverseOfTheFunctionalMatrix) {
  const Ws4Space space = perturbed_space();
  double worst_difference = 0.0, worst_identity = 0.0, worst_lu_identity = 0.0;
  for (int t = 0; t < space.num_elements(); ++t) {
    const Eigen::MatrixXd g = space.element_functionals(t);
    const Eigen::MatrixXd lu = g.partialPivLu().inverse();  // the former construction
    const Eigen::MatrixXd& exact = space.extraction(t);
    // Column m is the shape function of DOF m: compare each relative to its own size.
    for (int m = 0; m < 51; ++m)
      worst_difference = std::max(
          worst_difference, (exact.col(m) - lu.col(m)).cwiseAbs().maxCoeff() / exact.col(m).cwiseAbs().maxCoeff());
    const Eigen::MatrixXd id = Eigen::MatrixXd::Identity(51, 51);
    worst_identity = std::max(worst_identity, (g * exact - id).cwiseAbs().maxCoeff());
    worst_lu_identity = std::max(worst_lu_identity, (g * lu - id).cwiseAbs().maxCoeff());
  }
  std::cout << "exact vs LU extraction, worst relative column difference " << worst_difference
            << "; |G_K C_K - I|_max exact " << worst_identity << ", LU " << worst_lu_identity << "\n";
  EXPECT_LT(worst_difference, 1e-12);
  // G_K itself is evaluated in double with entries up to ~1e4: both products sit at its round-off.
  EXPECT_LT(worst_identity, 1e-9);
}

}  // namespace
}  // namespace iga::ws4
