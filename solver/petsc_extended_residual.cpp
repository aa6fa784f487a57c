#include "solver/petsc_extended_residual.hpp"

#ifdef IGA_WITH_PETSC

#include <petscsys.h>

namespace iga {

namespace {
/// Element entries gathered before being summed into the matrix: a few hundred megabytes at most.
constexpr std::size_t flush_size = std::size_t(1) << 23;
}  // namespace

ExtendedResidual::ExtendedResidual(int rows, std::vector<int> first_row, int rank)
    : first_row_(std::move(first_row)), rank_(rank), matrix_(rows, rows), load_(VectorXld::Zero(rows)) {}

void ExtendedResidual::add(const std::vector<int>& rows, const MatrixXld& K, const VectorXld& load) {
  const int m = static_cast<int>(rows.size());
  for (int i = 0; i < m; ++i) {
    load_(rows[i]) += load(i);
    for (int j = 0; j < m; ++j)
      if (K(i, j) != 0) pending_.emplace_back(rows[i], rows[j], K(i, j));
  }
  if (pending_.size() >= flush_size) flush();
}

void ExtendedResidual::flush() {
  if (pending_.empty()) return;
  // Duplicates are summed in long double, and so is the sum of the batches.
  Eigen::SparseMatrix<long double, Eigen::RowMajor> batch(matrix_.rows(), matrix_.cols());
  batch.setFromTriplets(pending_.begin(), pending_.end());
  std::vector<Eigen::Triplet<long double>>().swap(pending_);
  if (matrix_.nonZeros() == 0)
    matrix_ = std::move(batch);
  else
    matrix_ += batch;
}

std::vector<double> ExtendedResidual::owned_rows(const double* x) {
  flush();
  const int n = static_cast<int>(matrix_.rows());
  const VectorXld xl = Eigen::Map<const Eigen::VectorXd>(x, n).cast<long double>();
  const VectorXld part = load_ - matrix_ * xl;
  const int ranks = static_cast<int>(first_row_.size()) - 1;
  std::vector<int> counts(ranks);
  for (int r = 0; r < ranks; ++r) counts[r] = first_row_[r + 1] - first_row_[r];
  std::vector<long double> mine(counts[rank_]);
  MPI_Reduce_scatter(part.data(), mine.data(), counts.data(), MPI_LONG_DOUBLE, MPI_SUM, PETSC_COMM_WORLD);
  return std::vector<double>(mine.begin(), mine.end());
}

}  // namespace iga

#endif
