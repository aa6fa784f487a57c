#include "solver/petsc_extended_residual.hpp"

#ifdef IGA_WITH_PETSC

#include <petscsys.h>

#include <algorithm>
#include <stdexcept>

namespace iga {

namespace {
/// MPI_SUM for double-doubles (two doubles each, added with the error-free sum).
void add_double_doubles(void* in, void* inout, int* length, MPI_Datatype*) {
  const auto* a = static_cast<const DoubleDouble*>(in);
  auto* b = static_cast<DoubleDouble*>(inout);
  for (int i = 0; i < *length; ++i) b[i] = b[i] + a[i];
}
}  // namespace

ExtendedResidual::ExtendedResidual(const Constraints& c, std::vector<int> row_of_unknown, std::vector<int> first_row,
                                   int rank, SparseMatrix pattern)
    : c_(c),
      row_of_unknown_(std::move(row_of_unknown)),
      first_row_(std::move(first_row)),
      rank_(rank),
      pattern_(std::move(pattern)),
      values_(pattern_.nonZeros()),
      base_(c.values.size()) {}

void ExtendedResidual::add_load(const Eigen::VectorXd& load) {
  for (Eigen::Index i = 0; i < load.size(); ++i) base_[i] += load(i);
}

void ExtendedResidual::add(const std::vector<int>& dofs, const DoubleDoubleMatrix& K) {
  const int n = static_cast<int>(dofs.size());
  const bool keep = pattern_.nonZeros() > 0;
  const int* outer = pattern_.outerIndexPtr();
  const int* inner = pattern_.innerIndexPtr();
  for (int j = 0; j < n; ++j) {
    const double g = c_.values(dofs[j]);
    const int* first = keep ? inner + outer[dofs[j]] : nullptr;
    const int* last = keep ? inner + outer[dofs[j] + 1] : nullptr;
    for (int i = 0; i < n; ++i) {
      const DoubleDouble k = K(i, j);
      if (g != 0) base_[dofs[i]] -= k * g;
      if (keep) values_[std::lower_bound(first, last, dofs[i]) - inner] += k;
    }
  }
}

std::vector<double> ExtendedResidual::owned_rows(const double* u) const {
  const int dim = static_cast<int>(base_.size());
  const int nf = static_cast<int>(c_.free.size());
  std::vector<DoubleDouble> r = base_;
  if (u) {
    if (pattern_.nonZeros() == 0) throw std::logic_error("ExtendedResidual: the matrix was not kept");
    // y = T u, then r −= A y column by column (the pattern holds this rank's columns only).
    std::vector<double> y(dim, 0.0);
    for (int k = 0; k < nf; ++k) y[c_.free[k]] = u[row_of_unknown_[k]];
    for (const auto& t : c_.basis_change) y[t.row()] += t.value() * u[row_of_unknown_[t.col()]];
    const int* outer = pattern_.outerIndexPtr();
    const int* inner = pattern_.innerIndexPtr();
    for (int j = 0; j < dim; ++j) {
      if (y[j] == 0) continue;
      for (int p = outer[j]; p < outer[j + 1]; ++p) r[inner[p]] -= values_[p] * y[j];
    }
  }
  // Tᵀ r in the distributed numbering, then the sum over the ranks of the rows each owns.
  std::vector<DoubleDouble> reduced(nf);
  for (int k = 0; k < nf; ++k) reduced[row_of_unknown_[k]] = r[c_.free[k]];
  for (const auto& t : c_.basis_change) reduced[row_of_unknown_[t.col()]] += r[t.row()] * t.value();
  const int ranks = static_cast<int>(first_row_.size()) - 1;
  std::vector<int> counts(ranks);
  for (int q = 0; q < ranks; ++q) counts[q] = first_row_[q + 1] - first_row_[q];
  std::vector<DoubleDouble> mine(std::max(1, counts[rank_]));
  MPI_Datatype pair;
  MPI_Type_contiguous(2, MPI_DOUBLE, &pair);
  MPI_Type_commit(&pair);
  MPI_Op sum;
  MPI_Op_create(add_double_doubles, 1, &sum);
  MPI_Reduce_scatter(reduced.data(), mine.data(), counts.data(), pair, sum, PETSC_COMM_WORLD);
  MPI_Op_free(&sum);
  MPI_Type_free(&pair);
  std::vector<double> out(counts[rank_]);
  for (int i = 0; i < counts[rank_]; ++i) out[i] = mine[i].hi + mine[i].lo;
  return out;
}

}  // namespace iga

#endif
