#pragma once
/// @file
/// A sparse matrix kept beyond double precision as two doubles per entry, for residuals that
/// must be more accurate than the matrix a factorization sees.
///
/// Why: a stiffness matrix rounded to double carries entry errors δK ~ ε|K| that do not annihilate
/// the functions the matrix should map to the load (for the biharmonic problem K ~ h⁻² entries act
/// on O(1) coefficients to give an O(h²) load). Its exact solution then differs from the Galerkin
/// solution by K⁻¹ δK u ~ ε h⁻⁴ — an error floor that rises under refinement even for a solution
/// inside the space. Iterative refinement removes the factorization's round-off but not this:
/// its residual must be computed from K accumulated in extended precision.

#include <Eigen/Core>
#include <vector>

#include "assembly/sparsity.hpp"
#include "config/double_double.hpp"

namespace iga {

using MatrixXld = Eigen::Matrix<long double, Eigen::Dynamic, Eigen::Dynamic>;

/// The entry K_ij = high_ij + low_ij (a double-double).
struct SplitMatrix {
  SparseMatrix high;  ///< entries rounded to double (what factorizations use)
  Eigen::VectorXd low;  ///< entry − high, aligned with high.valuePtr(); may be empty (all zero)
  int rows() const { return static_cast<int>(high.rows()); }
};

/// Split double-double values aligned with `pattern` into high and low parts (kept exactly).
SplitMatrix split_matrix(const SparseMatrix& pattern, const std::vector<DoubleDouble>& values);

/// r = b − K x, products and sums in double-double, rounded to long double (K with both triangles
/// stored).
std::vector<long double> residual_extended(const SplitMatrix& K, const std::vector<long double>& x,
                                           const Eigen::VectorXd& b);

}  // namespace iga
