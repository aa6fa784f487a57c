#pragma once
/// @file
/// The residual of a distributed system with the matrix kept in double-double, for the right-hand
/// side and the iterative refinement of the PETSc path: the distributed counterpart of
/// reduced_residual (boundary_conditions.hpp), with the same element sums (split_matrix.hpp).
///
/// Each rank keeps its own elements' matrices, unreduced, summed in double-double into a pattern
/// of the functions of its part, and its part of b − A g (g the essential values). The residual of
/// the free unknowns, Tᵀ(b − A (g + T u)), is formed by every rank for the unknowns of its part,
/// sent to the rows' owners in double-double (PetscDistribution::sum_to_owners) and rounded to
/// double once there. A matrix rounded to double, or summed in long double, would carry entry
/// errors whose effect on the solution grows like h⁻⁴ for plates; this residual does not.

#include <Eigen/Core>
#include <vector>

#include "assembly/boundary_conditions.hpp"
#include "assembly/sparsity.hpp"
#include "config/double_double.hpp"

namespace iga {

class PetscDistribution;

class ExtendedResidual {
 public:
  /// `d`: the distribution after lay_out (its constraints and numbering). `pattern`: the couplings
  /// of this rank's elements (sparsity_pattern of their functions), or an empty matrix when only
  /// the right-hand side (u = 0) will be asked for.
  ExtendedResidual(const PetscDistribution& d, SparseMatrix pattern);

  /// Add this rank's part of the load (length: the functions of the rank's space).
  void add_load(const Eigen::VectorXd& load);
  /// Add an element's matrix (rows and columns: `dofs`).
  void add(const std::vector<int>& dofs, const DoubleDoubleMatrix& K);

  /// Collective: the rows this rank owns of b − A (g + T u), summed over the ranks in double-double
  /// and rounded once. `u`: the values of the rank's free unknowns (PetscDistribution::free_values),
  /// or null for u = 0 (the right-hand side).
  std::vector<double> owned_rows(const Eigen::VectorXd* u) const;
  /// This rank's part of uᵀ A u (u: coefficients of every unknown of the rank's space), the
  /// matrix of its own elements only: the parts add up to a(u, u) over the ranks.
  DoubleDouble energy_part(const Eigen::VectorXd& u) const;

 private:
  const PetscDistribution& d_;
  SparseMatrix pattern_;            ///< column-major; values unused
  std::vector<DoubleDouble> values_;  ///< aligned with pattern_'s entries
  std::vector<DoubleDouble> base_;    ///< this rank's part of b − A g
};

}  // namespace iga
