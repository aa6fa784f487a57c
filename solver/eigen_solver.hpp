#pragma once
/// @file
/// Generalized symmetric eigenproblems K x = λ M x (K symmetric positive semi-definite, M positive
/// definite, both with both triangles stored): the smallest eigenpairs by shift-and-invert Lanczos
/// (Spectra) with one CHOLMOD factor of K − σM, or all of them by a dense solver for small problems
/// (docs/eigen.md).

#include <Eigen/Core>
#include <string>

#include "assembly/sparsity.hpp"

namespace iga {

/// Eigenvalues ascending; the columns of `vectors` are the eigenvectors, M-orthonormal
/// (xᵢᵀ M xⱼ = δᵢⱼ) and signed so that their largest entry in magnitude is positive.
struct EigenPairs {
  Eigen::VectorXd values;
  Eigen::MatrixXd vectors;
};

struct EigenReport {
  std::string method;       ///< "spectra shift-invert lanczos + cholmod" or "dense"
  double shift = 0;         ///< σ of the factor K − σM
  double t_factorize = 0;   ///< seconds
  double t_solve = 0;       ///< seconds (Lanczos iterations, or the dense solve)
  int operations = 0;       ///< solves with the factor (Lanczos)
  double max_residual = 0;  ///< max over the pairs of ‖K x − λ M x‖ / ((‖K‖∞ + |λ| ‖M‖∞) ‖x‖)
};

/// The `count` smallest eigenpairs (count < rows). Shift σ = 0 when K is positive definite; σ < 0
/// below the spectrum when `may_be_singular` (nothing constrained: a closed surface with no
/// reaction, Neumann on the whole boundary, whose constants make K singular — in floating point
/// its Cholesky factorization may still succeed, with a useless factor) or when the factorization
/// at 0 fails. Throws NumericalError when Lanczos does not converge or a pair's residual is not small.
EigenPairs smallest_eigenpairs(const SparseMatrix& K, const SparseMatrix& M, int count, EigenReport& report,
                               bool may_be_singular = false);

/// Every eigenpair by a dense solver (LAPACK-free Eigen GeneralizedSelfAdjointEigenSolver, O(n³)):
/// for the whole discrete spectrum of problems up to a few thousand unknowns.
EigenPairs all_eigenpairs(const SparseMatrix& K, const SparseMatrix& M, EigenReport& report);

}  // namespace iga
