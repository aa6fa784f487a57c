// The Dirichlet Laplacian on the unit square, λ_mn = π²(m² + n²): the discrete eigenvalues of
// cubic C2 B-splines on 8 x 8 elements against GeoPDEs (ex_laplace_eig_square.m and its test,
// test_laplace_eig_square.m, which asserts these digits to 5e-13), and the Lanczos eigenvalues
// against a dense solver of the same matrices.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "solver/eigen_pipeline.hpp"
#include "solver/planar_formulation.hpp"
#include "spaces/point_location.hpp"
#include "tests/support/test_support.hpp"

namespace iga {
namespace {

const std::string kSquare = R"(
problem: {pde: poisson, boundary: {all: dirichlet}, eigen: {count: 6}}
domain: {type: rectangle, min: [0, 0], max: [1, 1]}
space: {type: bspline, degree: 3, elements: [8, 8]}
)";

/// u_h(x) = Σ c_i φ_i(x).
double value_at(const SpacePtr& space, const Eigen::VectorXd& c, const Point2& x) {
  const PointLocator locator(space);
  const PointBasis b = locator.basis_at({locator.locate(x)}).front();
  double u = 0;
  for (std::size_t k = 0; k < b.dofs.size(); ++k) u += c(b.dofs[k]) * b.value(k);
  return u;
}

TEST(EigenSquare, ReproducesGeoPdesEigenvalues) {
  const SpacePtr space = test::space_from_yaml(kSquare);
  const ProblemSpec problem = test::problem_from_yaml(kSquare);
  const PlanarFormulation f(*space, problem);
  SerialEigenBackend backend;
  const DiscreteSolution s = solve_eigen_pipeline(f, backend);
  // λ/π² from GeoPDEs: the same space (degree 3, C2, 8 x 8), exact quadrature.
  const double geopdes[] = {2.00000025982960, 5.00004032992316, 5.00004032992316,
                            8.00008040001672, 10.00134779087585, 10.00134779087585};
  ASSERT_EQ(s.eigenvalues.size(), 6);
  const double pi2 = std::numbers::pi * std::numbers::pi;
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(s.eigenvalues(i) / pi2, geopdes[i], 1e-12 * geopdes[i]) << "index " << i;
  // (8 + 3)² functions, the 4·11 − 4 = 40 on the boundary fixed.
  EXPECT_EQ(s.result.dofs, 121);
  EXPECT_EQ(s.result.free_dofs, 81);
  EXPECT_LT(s.solve.relative_residual, 1e-10);  // the eigensolve's largest residual
}

TEST(EigenSquare, ModesAreMassOrthonormalAndZeroOnTheBoundary) {
  const SpacePtr space = test::space_from_yaml(kSquare);
  const ProblemSpec problem = test::problem_from_yaml(kSquare);
  const PlanarFormulation f(*space, problem);
  SerialEigenBackend backend;
  const DiscreteSolution s = solve_eigen_pipeline(f, backend);
  const SparseMatrix M = f.matrix({mass_integrator()}).high;
  const Eigen::MatrixXd gram = s.modes.transpose() * M * s.modes;
  EXPECT_LE((gram - Eigen::MatrixXd::Identity(6, 6)).lpNorm<Eigen::Infinity>(), 1e-12);
  // The first mode, sin(πx) sin(πy) / ‖·‖ = 2 sin(πx) sin(πy), to the pointwise error of cubics,
  // O(h⁴) with h⁴ = 2.4e-4 (measured 1.4e-4); the sign fixed by the largest coefficient.
  EXPECT_NEAR(value_at(space, s.modes.col(0), Point2(0.5, 0.5)), 2.0, 2.4e-4);
  EXPECT_GT(std::abs(value_at(space, s.modes.col(0), Point2(0.5, 0.5)) - 2.0), 1e-6);  // not interpolated
  EXPECT_NEAR(value_at(space, s.modes.col(0), Point2(0.0, 0.3)), 0.0, 1e-14);
}

TEST(EigenSquare, LanczosAgreesWithTheDenseSolver) {
  const SpacePtr space = test::space_from_yaml(kSquare);
  const ProblemSpec problem = test::problem_from_yaml(kSquare);
  const PlanarFormulation f(*space, problem);
  SerialEigenBackend backend;
  const DiscreteSolution s = solve_eigen_pipeline(f, backend);
  EigenReport dense;
  const Eigen::VectorXd all = backend.spectrum(dense);
  ASSERT_EQ(all.size(), 81);
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(s.eigenvalues(i), all(i), 1e-12 * all(i));
  // The discrete eigenvalues bound the exact ones from above (Rayleigh–Ritz): λ_h,1 >= 2π².
  EXPECT_GE(all(0), 2 * std::numbers::pi * std::numbers::pi);
}

}  // namespace
}  // namespace iga
