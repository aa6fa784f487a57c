#pragma once
/// @file
/// The residual of a distributed system with the matrix kept beyond double precision, for the
/// iterative refinement of the PETSc path (the distributed counterpart of split_matrix.hpp).
///
/// Each rank keeps its own elements' contributions, in long double, to the reduced matrix and load
/// (for the rows they touch, owned by this rank or not): the ranks' parts sum to the system. The
/// residual b − K x of every rank's part is summed over the ranks in long double (MPI_SUM on
/// MPI_LONG_DOUBLE) and rounded to double once, on the rank that owns the row. A double matrix
/// assembled by PETSc would carry entry errors ε|K| whose effect on the solution grows like
/// ε h⁻⁴ for plates; this residual does not.

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

#include "assembly/split_matrix.hpp"

namespace iga {

class ExtendedResidual {
 public:
  using VectorXld = Eigen::Matrix<long double, Eigen::Dynamic, 1>;

  /// A system of `rows` unknowns; rank r owns the rows first_row[r] .. first_row[r+1] (PETSc's
  /// contiguous layout), this process is `rank`.
  ExtendedResidual(int rows, std::vector<int> first_row, int rank);

  /// Add an element's matrix K (rows and columns `rows`, global row numbers) and load.
  void add(const std::vector<int>& rows, const MatrixXld& K, const VectorXld& load);
  /// Add `value` to the load of row `row`.
  void add_load(int row, long double value) { load_(row) += value; }

  /// Collective: (b − K x) on this rank's own rows, each summed over all ranks' parts in long
  /// double and rounded once. `x` is the whole vector (every row, global numbering).
  std::vector<double> owned_rows(const double* x);

 private:
  void flush();

  std::vector<int> first_row_;
  int rank_;
  Eigen::SparseMatrix<long double, Eigen::RowMajor> matrix_;
  std::vector<Eigen::Triplet<long double>> pending_;
  VectorXld load_;
};

}  // namespace iga
