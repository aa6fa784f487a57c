#include "solver/petsc_extended_residual.hpp"

#ifdef IGA_WITH_PETSC

#include <algorithm>
#include <stdexcept>

#include "solver/petsc_distribution.hpp"

namespace iga {

ExtendedResidual::ExtendedResidual(const PetscDistribution& d, SparseMatrix pattern)
    : d_(d), pattern_(std::move(pattern)), values_(pattern_.nonZeros()), base_(d.constraints().values.size()) {}

void ExtendedResidual::add_load(const Eigen::VectorXd& load) {
  for (Eigen::Index i = 0; i < load.size(); ++i) base_[i] += load(i);
}

void ExtendedResidual::add(const std::vector<int>& dofs, const DoubleDoubleMatrix& K) {
  const Constraints& c = d_.constraints();
  const int n = static_cast<int>(dofs.size());
  const bool keep = pattern_.nonZeros() > 0;
  const int* outer = pattern_.outerIndexPtr();
  const int* inner = pattern_.innerIndexPtr();
  for (int j = 0; j < n; ++j) {
    const double g = c.values(dofs[j]);
    if (g == 0 && !keep) continue;  // nothing to add: most columns of a Krylov solve's elements
    const int* first = keep ? inner + outer[dofs[j]] : nullptr;
    const int* last = keep ? inner + outer[dofs[j] + 1] : nullptr;
    for (int i = 0; i < n; ++i) {
      const DoubleDouble k = K(i, j);
      if (g != 0) base_[dofs[i]] -= k * g;
      if (keep) values_[std::lower_bound(first, last, dofs[i]) - inner] += k;
    }
  }
}

std::vector<double> ExtendedResidual::owned_rows(const Eigen::VectorXd* u) const {
  const Constraints& c = d_.constraints();
  const int dim = static_cast<int>(base_.size());
  const int nf = static_cast<int>(c.free.size());
  std::vector<DoubleDouble> r = base_;
  if (u) {
    if (pattern_.nonZeros() == 0) throw std::logic_error("ExtendedResidual: the matrix was not kept");
    // y = T u, then r −= A y column by column (the pattern holds this rank's elements only).
    std::vector<double> y(dim, 0.0);
    for (int k = 0; k < nf; ++k) y[c.free[k]] = (*u)(k);
    for (const auto& t : c.basis_change) y[t.row()] += t.value() * (*u)(t.col());
    const int* outer = pattern_.outerIndexPtr();
    const int* inner = pattern_.innerIndexPtr();
    for (int j = 0; j < dim; ++j) {
      if (y[j] == 0) continue;
      for (int p = outer[j]; p < outer[j + 1]; ++p) r[inner[p]] -= values_[p] * y[j];
    }
  }
  // Tᵀ r for this rank's unknowns, then the sum over the ranks at the rows' owners.
  std::vector<DoubleDouble> reduced(nf);
  for (int k = 0; k < nf; ++k) reduced[k] = r[c.free[k]];
  for (const auto& t : c.basis_change) reduced[t.col()] += r[t.row()] * t.value();
  return d_.sum_to_owners(reduced);
}

DoubleDouble ExtendedResidual::energy_part(const Eigen::VectorXd& u) const {
  if (pattern_.nonZeros() == 0) throw std::logic_error("ExtendedResidual: the matrix was not kept");
  const int* outer = pattern_.outerIndexPtr();
  const int* inner = pattern_.innerIndexPtr();
  DoubleDouble sum;
  for (Eigen::Index j = 0; j < pattern_.outerSize(); ++j) {
    if (u(j) == 0) continue;
    DoubleDouble column;  // (A u)_i u_i summed over the column's rows i, times u_j below
    for (int p = outer[j]; p < outer[j + 1]; ++p) column += values_[p] * u(inner[p]);
    sum += column * u(j);
  }
  return sum;
}

}  // namespace iga

#endif
