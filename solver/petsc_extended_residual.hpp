#pragma once
/// @file
/// The residual of a distributed system with the matrix kept in double-double, for the right-hand
/// side and the iterative refinement of the PETSc path: the distributed counterpart of
/// reduced_residual (boundary_conditions.hpp), with the same element sums (split_matrix.hpp).
///
/// Each rank keeps its own elements' matrices, unreduced, summed in double-double into a pattern
/// of the functions they touch, and its part of b − A g (g the essential values). The residual of
/// the free unknowns, Tᵀ(b − A (g + T u)), is formed by every rank for its part, summed over the
/// ranks in double-double (MPI_Reduce_scatter with a double-double sum) and rounded to double once,
/// on the rank that owns the row. A matrix rounded to double, or summed in long double, would carry
/// entry errors whose effect on the solution grows like h⁻⁴ for plates; this residual does not.

#include <Eigen/Core>
#include <vector>

#include "assembly/boundary_conditions.hpp"
#include "assembly/sparsity.hpp"
#include "config/double_double.hpp"

namespace iga {

class ExtendedResidual {
 public:
  /// `c`: the essential conditions; `row_of_unknown`: free unknown k (position in c.free) → its
  /// row in the distributed numbering, where rank r owns rows first_row[r] .. first_row[r+1];
  /// this process is `rank`. `pattern`: the couplings of this rank's elements (sparsity_pattern of
  /// their dofs), or an empty matrix when only the right-hand side (u = 0) will be asked for.
  ExtendedResidual(const Constraints& c, std::vector<int> row_of_unknown, std::vector<int> first_row, int rank,
                   SparseMatrix pattern);

  /// Add this rank's part of the load (length: dimension).
  void add_load(const Eigen::VectorXd& load);
  /// Add an element's matrix (rows and columns: `dofs`).
  void add(const std::vector<int>& dofs, const DoubleDoubleMatrix& K);

  /// Collective: the free rows of b − A (g + T u) owned by this rank, summed over the ranks in
  /// double-double and rounded once. `u` is the whole vector of unknowns in the distributed
  /// numbering, or null for u = 0 (the right-hand side).
  std::vector<double> owned_rows(const double* u) const;

 private:
  const Constraints& c_;
  std::vector<int> row_of_unknown_, first_row_;
  int rank_;
  SparseMatrix pattern_;            ///< column-major; values unused
  std::vector<DoubleDouble> values_;  ///< aligned with pattern_'s entries
  std::vector<DoubleDouble> base_;    ///< this rank's part of b − A g
};

}  // namespace iga
