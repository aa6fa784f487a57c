#include "config/errors.hpp"

#ifdef IGA_WITH_PETSC

#include "solver/petsc_distribution.hpp"

#include <algorithm>
#include <cstdio>

#include "assembly/boundary_conditions.hpp"
#include "assembly/element_subset_assembly.hpp"
#include "assembly/sparsity.hpp"
#include "solver/petsc_extended_residual.hpp"
#include "solver/petsc_session.hpp"

namespace iga {

namespace {

/// The unknowns an element with functions `dofs` couples (sorted, unique), and T_e with
/// u|element = values|element + T_e u_unknowns: the rows `dofs` of free_basis (boundary_conditions.hpp)
/// on those columns.
using FreeBasis = Eigen::SparseMatrix<double, Eigen::RowMajor>;
void element_unknowns(const FreeBasis& T, const std::vector<int>& dofs, std::vector<int>& unknowns,
                      Eigen::MatrixXd* T_e = nullptr) {
  unknowns.clear();
  for (int d : dofs)
    for (FreeBasis::InnerIterator it(T, d); it; ++it) unknowns.push_back(static_cast<int>(it.col()));
  std::sort(unknowns.begin(), unknowns.end());
  unknowns.erase(std::unique(unknowns.begin(), unknowns.end()), unknowns.end());
  if (!T_e) return;
  T_e->setZero(static_cast<int>(dofs.size()), static_cast<int>(unknowns.size()));
  for (int i = 0; i < static_cast<int>(dofs.size()); ++i)
    for (FreeBasis::InnerIterator it(T, dofs[i]); it; ++it)
      (*T_e)(i, std::lower_bound(unknowns.begin(), unknowns.end(), it.col()) - unknowns.begin()) = it.value();
}

}  // namespace

std::string petsc_message(PetscErrorCode code) {
  const char* text = nullptr;
  char* specific = nullptr;
  PetscErrorMessage(code, &text, &specific);
  if (specific && *specific) return specific;
  return text ? text : "error " + std::to_string(code);
}

void petsc_check(PetscErrorCode code, const char* what) {
  if (code != 0)
    throw std::runtime_error(std::string("PETSc failed in ") + what + " (error " + std::to_string(code) +
                             "): " + petsc_message(code));
}

PetscDistribution::PetscDistribution(const Space& space, const std::function<void(const std::string&)>& say)
    : space_(space), rank_(mpi_rank()), ranks_(mpi_size()) {
  on_every_rank([&] {
    if (say)
      say("partitioning " + std::to_string(space.num_elements()) + " elements over " + std::to_string(ranks_) +
          " rank(s)");
    owner_ = partition_elements(element_centres(space), ranks_);
    for (int e = 0; e < space.num_elements(); ++e)
      if (owner_[e] == rank_) mine_.push_back(e);
  });
}

WorkShare PetscDistribution::share() const {
  return {&mine_, [](double part) {
            MPI_Allreduce(MPI_IN_PLACE, &part, 1, MPI_DOUBLE, MPI_SUM, PETSC_COMM_WORLD);
            return part;
          }};
}

void PetscDistribution::lay_out(const Constraints& c, SparseMatrix* pattern,
                                const std::function<void(const std::string&)>& say) {
  constraints_ = c;
  // Local work first (every rank the same, apart from its elements): an error found here is
  // raised on all ranks together before any collective call.
  on_every_rank([&] {
    basis_ = free_basis(c);
    const ElementDofTable table = collect_element_dofs(space_);
    std::vector<int> unknown_offsets{0}, unknowns, dofs, local;
    ElementDofTable my_table;
    my_table.offsets.push_back(0);
    for (int e = 0; e < table.num_elements(); ++e) {
      dofs.assign(table.begin(e), table.begin(e + 1));
      element_unknowns(basis_, dofs, local);
      unknowns.insert(unknowns.end(), local.begin(), local.end());
      unknown_offsets.push_back(static_cast<int>(unknowns.size()));
      if (pattern && owner_[e] == rank_) {
        my_table.dofs.insert(my_table.dofs.end(), dofs.begin(), dofs.end());
        my_table.offsets.push_back(static_cast<int>(my_table.dofs.size()));
      }
    }
    layout_ = layout_unknowns(unknown_offsets, unknowns, owner_, static_cast<int>(c.free.size()), ranks_);
    couplings_ = row_couplings(unknown_offsets, unknowns, layout_, rank_);
    if (pattern) *pattern = sparsity_pattern(my_table, space_.dimension());
  });
  long long totals[2] = {couplings_.off_rank, couplings_.total};
  MPI_Allreduce(MPI_IN_PLACE, totals, 2, MPI_LONG_LONG, MPI_SUM, PETSC_COMM_WORLD);
  if (ranks_ > 1 && say) {
    char share[32];
    std::snprintf(share, sizeof share, "%.3g %%", 100.0 * static_cast<double>(totals[0]) / std::max(1LL, totals[1]));
    say("matrix couplings between ranks: " + std::to_string(totals[0]) + " of " + std::to_string(totals[1]) + " (" +
        share + ")");
  }
}

void PetscDistribution::matrix(const Formulation& f, const std::vector<FormTerm>& terms, ExtendedResidual* extended,
                               Mat& A) const {
  const PetscInt n_global = static_cast<PetscInt>(constraints_.free.size());
  const PetscInt n_local = layout_.first_row[rank_ + 1] - layout_.first_row[rank_];
  petsc_check(MatCreate(PETSC_COMM_WORLD, &A), "MatCreate");
  petsc_check(MatSetSizes(A, n_local, n_local, n_global, n_global), "MatSetSizes");
  petsc_check(MatSetType(A, MATAIJ), "MatSetType");
  const std::vector<PetscInt> d_nnz(couplings_.on_rank_columns.begin(), couplings_.on_rank_columns.end());
  const std::vector<PetscInt> o_nnz(couplings_.off_rank_columns.begin(), couplings_.off_rank_columns.end());
  petsc_check(MatSeqAIJSetPreallocation(A, 0, d_nnz.data()), "MatSeqAIJSetPreallocation");
  petsc_check(MatMPIAIJSetPreallocation(A, 0, d_nnz.data(), 0, o_nnz.data()), "MatMPIAIJSetPreallocation");
  petsc_check(MatSetOption(A, MAT_SYMMETRIC, PETSC_TRUE), "MatSetOption");
  petsc_check(MatSetOption(A, MAT_SPD, PETSC_TRUE), "MatSetOption");
  on_every_rank([&] {
    std::vector<int> local;
    std::vector<PetscInt> rows;
    Eigen::MatrixXd T;
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> K;
    // Tᵀ A T in double for the factorization; A itself, in double-double, for the residuals.
    const auto add_element = [&](int, const std::vector<int>& dofs, const DoubleDoubleMatrix& A_e) {
      if (extended) extended->add(dofs, A_e);
      element_unknowns(basis_, dofs, local, &T);
      if (local.empty()) return;
      // Coefficient-wise products: Eigen's blocked ones would start a thread team per element.
      K = T.transpose().lazyProduct(A_e.hi.lazyProduct(T));
      rows.resize(local.size());
      for (std::size_t i = 0; i < local.size(); ++i) rows[i] = layout_.global[local[i]];
      const PetscInt m = static_cast<PetscInt>(rows.size());
      petsc_check(MatSetValues(A, m, rows.data(), m, rows.data(), K.data(), ADD_VALUES), "MatSetValues");
    };
    for_each_element_matrix(space_, mine_, terms, f.quadrature_degree(), add_element);
  });
  petsc_check(MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
  petsc_check(MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
}

Eigen::VectorXd PetscDistribution::free_values(const PetscScalar* all) const {
  Eigen::VectorXd u_free(constraints_.free.size());
  for (Eigen::Index k = 0; k < u_free.size(); ++k) u_free(k) = all[layout_.global[k]];
  return u_free;
}

}  // namespace iga

#endif
