// Adaptive T-mesh refinement driven by the first eigenpair (refinement.type: adaptive with
// problem.eigen): the L-shape's λ₁ = 9.6397238440219 (Trefethen and Betcke, "Computed eigenmodes of
// planar regions", 2006), whose eigenfunction is singular like r^(2/3) at the re-entrant corner.
// Uniform refinement gives λ₁ the rate 4/3 in h, 2/3 in the number of DOFs N (eigen_rates_test);
// the residual indicator of −Δu = λu with Dörfler marking recovers the rate of smooth
// eigenfunctions, |λ_h − λ| ~ N^(−p) = N^(−3) for cubics (the square of the energy error N^(−p/2),
// Babuška–Osborn).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "solver/eigen_table.hpp"
#include "tests/support/test_support.hpp"

namespace iga {
namespace {

TEST(EigenAdaptive, LShapeFirstEigenvalueRecoversTheSmoothRateInDofs) {
  const std::string yaml = R"yaml(
problem: {pde: poisson, boundary: {all: dirichlet}, eigen: {count: 1, exact_eigenvalues: [9.6397238440219]}}
domain: {type: l_shape, min: [-1, -1], max: [1, 1]}
space: {type: tmesh, section: poly, n: 3, regularity: 1, elements: [4, 4]}
refinement: {type: adaptive, marking: 0.5, levels: 17}
)yaml";
  const StudySettings settings = parse_study(ConfigNode::load_string(yaml, "test.yaml"), "test.yaml", 0, "");
  const StudyResult result = run_study(settings, [](const std::string&) {});
  const std::vector<EigenRow> rows = eigen_rows(result.eigen, settings.problem.eigen->exact);
  ASSERT_EQ(rows.size(), 17u);
  for (const EigenRow& r : rows)
    std::printf("level %2d dofs %5d  λ₁ %.15f  error %.3e\n", r.level, r.dofs, r.eigenvalue, r.relative_error.value());
  for (std::size_t k = 1; k < rows.size(); ++k) {
    // Conforming (λ_h ≥ λ, min–max) and nested (refining only adds functions): λ₁,h decreases.
    EXPECT_GT(rows[k].eigenvalue, 9.6397238440219) << "level " << k;
    EXPECT_LE(rows[k].eigenvalue, rows[k - 1].eigenvalue * (1 + 1e-13)) << "level " << k;
  }
  // The rate in N over the last half of the levels (296 to 1296 DOFs): at least 2.5 against the
  // optimal 3 (uniform: 0.67). Measured 4.5 here (the error still falls faster than N^(−3) while
  // the corner is being resolved; 3.3 from 1044 to 8924 DOFs, configs/eigen-laplace-lshape-adaptive.yaml).
  const EigenRow& a = rows[rows.size() / 2];
  const EigenRow& b = rows.back();
  const double rate = std::log(*a.relative_error / *b.relative_error) / std::log(double(b.dofs) / a.dofs);
  std::printf("rate in N from %d to %d DOFs: %.2f\n", a.dofs, b.dofs, rate);
  EXPECT_GT(rate, 2.5);
  // Uniform cubic T-splines need 12804 DOFs for 2.8e-3 (docs/eigen.md); here under 2000 reach
  // below 1e-6.
  EXPECT_LT(b.dofs, 2000);
  EXPECT_LT(*b.relative_error, 1e-6);
}

}  // namespace
}  // namespace iga
