#pragma once
/// @file
/// The collocation matrix of the WS4 element, A(j, i) = ρ_j(B_i) for the 51 functionals of the
/// notes §2.2 and the 51 reference simplex splines, as exact rationals (notes §6), and its exact
/// inverse: the B-coefficients of the spline with functionals ρ are b = A⁻¹ ρ (the notes write
/// the same matrix as A^{-T}, with A indexed (i, j)). The inverse is computed once in exact
/// rational arithmetic (GiNaC), so the extraction C_K = A⁻¹ T_K carries no inversion error
/// (cond₂ A ≈ 5.4e5).

#include <Eigen/Core>
#include <vector>

namespace iga::ws4 {

/// One nonzero ρ_j(B_i) = numerator / denominator, j = 1..51.
struct CollocationEntry {
  int j;
  long numerator, denominator;
};

/// Nonzeros of the 51 columns B_1 … B_51 of A (notes §6), index i for B_{i+1}.
const std::vector<std::vector<CollocationEntry>>& ws4_collocation_table();

/// A in double, (j, i) = ρ_{j+1}(B_{i+1}), 51 x 51.
Eigen::MatrixXd ws4_collocation_matrix();

/// Row-major: the extraction combines whole rows of these.
using Matrix51L = Eigen::Matrix<long double, 51, 51, Eigen::RowMajor>;

/// A⁻¹, (i, j) = coefficient of ρ_{j+1} in b_{i+1}: the exact rational inverse, each entry rounded
/// to long double (built on first use, then shared; thread-safe).
const Matrix51L& ws4_coefficients_from_functionals();

}  // namespace iga::ws4
