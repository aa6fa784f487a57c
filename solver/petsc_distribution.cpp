#include "config/errors.hpp"

#ifdef IGA_WITH_PETSC

#include "solver/petsc_distribution.hpp"

#include <algorithm>
#include <climits>
#include <numeric>
#include <tuple>

#include "assembly/assembler.hpp"
#include "assembly/boundary_conditions.hpp"
#include "assembly/element_subset_assembly.hpp"
#include "solver/petsc_extended_residual.hpp"
#include "solver/petsc_session.hpp"
#include "solver/rank_part.hpp"
#include "spaces/space_part.hpp"

namespace iga {

namespace {

/// A star forest from `leaves` (global indices into a vector laid out by `map`) to the roots of
/// that layout. Collective.
PetscSF make_sf(PetscLayout map, const std::vector<PetscInt>& leaves) {
  PetscSF sf = nullptr;
  petsc_check(PetscSFCreate(PETSC_COMM_WORLD, &sf), "PetscSFCreate");
  petsc_check(PetscSFSetGraphLayout(sf, map, static_cast<PetscInt>(leaves.size()), nullptr, PETSC_COPY_VALUES,
                                    leaves.data()),
              "PetscSFSetGraphLayout");
  petsc_check(PetscSFSetUp(sf), "PetscSFSetUp");
  return sf;
}

PetscLayout make_layout(PetscInt local, PetscInt global) {
  PetscLayout map = nullptr;
  petsc_check(PetscLayoutCreateFromSizes(PETSC_COMM_WORLD, local, global, 1, &map), "PetscLayoutCreateFromSizes");
  return map;
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
    if (const auto* part = dynamic_cast<const SpacePart*>(&space)) {
      mine_ = part->owned_elements();
      global_dofs_ = part->global_dofs();
      whole_dimension_ = part->whole().dimension();
      whole_elements_ = part->whole().num_elements();
      return;
    }
    if (say)
      say("partitioning " + std::to_string(space.num_elements()) + " elements over " + std::to_string(ranks_) +
          " rank(s)");
    mine_ = rank_elements(space, rank_, ranks_);
    whole_dimension_ = space.dimension();
    whole_elements_ = space.num_elements();
  });
}

PetscDistribution::~PetscDistribution() { PetscSFDestroy(&rows_sf_); }

WorkShare PetscDistribution::share() const { return {&mine_, true}; }

void PetscDistribution::element_unknowns(int element, std::vector<int>& dofs, std::vector<int>& unknowns,
                                         Eigen::MatrixXd* T_e) const {
  space_.element_dofs(element, dofs);
  expand_component_dofs(dofs, components_, space_.dimension());
  unknowns.clear();
  for (int d : dofs)
    for (decltype(basis_)::InnerIterator it(basis_, d); it; ++it) unknowns.push_back(static_cast<int>(it.col()));
  std::sort(unknowns.begin(), unknowns.end());
  unknowns.erase(std::unique(unknowns.begin(), unknowns.end()), unknowns.end());
  if (!T_e) return;
  T_e->setZero(static_cast<int>(dofs.size()), static_cast<int>(unknowns.size()));
  for (int i = 0; i < static_cast<int>(dofs.size()); ++i)
    for (decltype(basis_)::InnerIterator it(basis_, dofs[i]); it; ++it)
      (*T_e)(i, std::lower_bound(unknowns.begin(), unknowns.end(), it.col()) - unknowns.begin()) = it.value();
}

namespace {
/// What a rank offers for owning unknown g; the least offer wins. Even g go to the lowest rank
/// that couples them, odd g to the highest, so the rows on a cut between two ranks are shared
/// evenly: with every row of the cut on the lower rank (1 % of the rows on two ranks at 10⁶
/// B-spline DOFs) that rank's matrix products and assembly lagged the other's by more than its
/// extra rows (CG with Jacobi, 300 products: the other rank waited 0.6 s for it in the products,
/// 0.15 s when shared; the CG + GAMG run's assembly 0.1 s faster on two ranks, medians of five).
int ownership_key(PetscInt g, int rank) { return g % 2 == 0 ? rank : INT_MAX - 1 - rank; }
}  // namespace

void PetscDistribution::lay_out(const Constraints& c, const std::function<void(const std::string&)>& say,
                                int components) {
  constraints_ = c;
  components_ = components;
  const int n = static_cast<int>(c.free.size());
  std::vector<PetscInt> global(n);
  std::vector<int> candidate(n, INT_MAX);
  // Local work first: an error found here is raised on all ranks together before any collective call.
  on_every_rank([&] {
    if (c.values.size() != static_cast<Eigen::Index>(components) * space_.dimension())
      throw std::logic_error("PetscDistribution: conditions of " + std::to_string(c.values.size()) +
                             " unknowns for " + std::to_string(components) + " component(s) of " +
                             std::to_string(space_.dimension()) + " functions");
    basis_ = free_basis(c);
    // Component q of function i (unknown q·N + i of the space, N its dimension) is unknown
    // q·N_whole + (i's number in the whole space) of the whole problem.
    const int local_n = space_.dimension();
    for (int k = 0; k < n; ++k) {
      const int q = c.free[k] / local_n, i = c.free[k] % local_n;
      global[k] = static_cast<PetscInt>(q) * static_cast<PetscInt>(whole_dimension_) +
                  (global_dofs_.empty() ? i : global_dofs_[i]);
    }
    std::vector<int> dofs, unknowns;
    for (int e : mine_) {
      element_unknowns(e, dofs, unknowns, nullptr);
      for (int k : unknowns) candidate[k] = ownership_key(global[k], rank_);
    }
  });
  // The directory: unknown g of the whole problem has its entry on the rank of block g. Each unknown
  // goes to the least key among the ranks whose elements couple it (ownership_key: the lowest
  // of them for even g, the highest for odd g); the owners number theirs contiguously.
  PetscLayout functions = make_layout(PETSC_DECIDE, static_cast<PetscInt>(components_ * whole_dimension_));
  PetscSF directory = make_sf(functions, global);
  PetscInt n_roots = 0;
  petsc_check(PetscLayoutGetLocalSize(functions, &n_roots), "PetscLayoutGetLocalSize");
  std::vector<int> owner_at_root(n_roots, INT_MAX), owner(n);
  petsc_check(PetscSFReduceBegin(directory, MPI_INT, candidate.data(), owner_at_root.data(), MPI_MIN), "PetscSFReduce");
  petsc_check(PetscSFReduceEnd(directory, MPI_INT, candidate.data(), owner_at_root.data(), MPI_MIN), "PetscSFReduce");
  petsc_check(PetscSFBcastBegin(directory, MPI_INT, owner_at_root.data(), owner.data(), MPI_REPLACE), "PetscSFBcast");
  petsc_check(PetscSFBcastEnd(directory, MPI_INT, owner_at_root.data(), owner.data(), MPI_REPLACE), "PetscSFBcast");
  std::vector<int> own;  // this rank's unknowns, in the order of their global numbers
  for (int k = 0; k < n; ++k) {
    if (owner[k] == INT_MAX)  // every function lives on an element, and every element has a rank
      throw std::logic_error("PetscDistribution: an unknown that no rank's elements couple");
    if (owner[k] == ownership_key(global[k], rank_)) own.push_back(k);
  }
  std::sort(own.begin(), own.end(), [&](int a, int b) { return global[a] < global[b]; });
  owned_rows_ = static_cast<PetscInt>(own.size());
  PetscInt first = 0;
  MPI_Exscan(&owned_rows_, &first, 1, MPIU_INT, MPI_SUM, PETSC_COMM_WORLD);
  if (rank_ == 0) first = 0;
  MPI_Allreduce(&owned_rows_, &rows_, 1, MPIU_INT, MPI_SUM, PETSC_COMM_WORLD);
  std::vector<PetscInt> offered(n, -1), row_at_root(n_roots, -1);
  for (std::size_t i = 0; i < own.size(); ++i) offered[own[i]] = first + static_cast<PetscInt>(i);
  row_.assign(n, -1);
  petsc_check(PetscSFReduceBegin(directory, MPIU_INT, offered.data(), row_at_root.data(), MPI_MAX), "PetscSFReduce");
  petsc_check(PetscSFReduceEnd(directory, MPIU_INT, offered.data(), row_at_root.data(), MPI_MAX), "PetscSFReduce");
  petsc_check(PetscSFBcastBegin(directory, MPIU_INT, row_at_root.data(), row_.data(), MPI_REPLACE), "PetscSFBcast");
  petsc_check(PetscSFBcastEnd(directory, MPIU_INT, row_at_root.data(), row_.data(), MPI_REPLACE), "PetscSFBcast");
  PetscSFDestroy(&directory);
  PetscLayoutDestroy(&functions);

  PetscLayout rows = make_layout(owned_rows_, rows_);
  PetscSFDestroy(&rows_sf_);
  rows_sf_ = make_sf(rows, row_);
  PetscLayoutDestroy(&rows);
  if (ranks_ > 1 && say) say("unknowns of this rank's part: " + std::to_string(n) + ", rows it owns: " +
                             std::to_string(owned_rows_) + " of " + std::to_string(rows_));
}

PetscDistribution::Rows PetscDistribution::couplings() const {
  const int n = static_cast<int>(row_.size());
  Rows rows;
  // The unknowns of each of this rank's elements (CSR), and its transpose.
  std::vector<int>& offsets = rows.element_offsets;
  std::vector<int>& unknowns = rows.element_unknowns;
  std::vector<int> dofs, local;
  offsets.reserve(mine_.size() + 1);
  offsets.push_back(0);
  for (int e : mine_) {
    element_unknowns(e, dofs, local, nullptr);
    unknowns.insert(unknowns.end(), local.begin(), local.end());
    offsets.push_back(static_cast<int>(unknowns.size()));
  }
  std::vector<int>& first = rows.row_first;
  first.assign(n + 1, 0);
  rows.row_elements.resize(unknowns.size());
  for (int k : unknowns) ++first[k + 1];
  for (int k = 0; k < n; ++k) first[k + 1] += first[k];
  {
    std::vector<int> fill(first.begin(), first.end() - 1);
    for (int i = 0; i + 1 < static_cast<int>(offsets.size()); ++i)
      for (int p = offsets[i]; p < offsets[i + 1]; ++p) rows.row_elements[fill[unknowns[p]]++] = i;
  }
  // Row k is the union of its elements' unknowns: marked once each (a row of cubic splines meets
  // 16 elements of 16 unknowns for its 49 couplings), so only the distinct ones are sorted.
  rows.mark.assign(n, 0);
  std::vector<int>& start = rows.start;
  start.assign(n + 1, 0);
  for (int k = 0; k < n; ++k) rows.for_each_coupling(k, [&](int) { ++start[k + 1]; });
  for (int k = 0; k < n; ++k) start[k + 1] += start[k];
  // Blocks of about 2^23 entries (32 MB of columns, 64 MB of values). Two or three of them are
  // alive at once on every rank whatever the rank count (at 10⁶ cubic B-spline DOFs 202 MB of a
  // rank's 710 MB assembly heap on two ranks, 147 of 410 MB on four), yet smaller ones cost more
  // than they save where GAMG's set-up is the peak: it then runs 4–11 % slower on two ranks (2^21;
  // most likely its arrays no longer land on the freed, already resident pages), and with 2^19 one
  // rank of the 10⁷-DOF run peaked 0.5 GB higher. docs/parallel.md has the numbers.
  constexpr long long block_entries = 1LL << 23;
  rows.rows_per_block = static_cast<int>(std::clamp<long long>(
      block_entries * n / std::max(1, start[n]), 1, std::max(1, n)));
  const int blocks = static_cast<int>((static_cast<long long>(n) + rows.rows_per_block - 1) / rows.rows_per_block);
  rows.columns.resize(blocks);
  rows.values.resize(blocks);
  rows.filled.assign(blocks, 0);
  rows.complete_after.assign(blocks, -1);
  for (int k = 0; k < n; ++k)
    for (int q = first[k]; q < first[k + 1]; ++q) {
      int& last = rows.complete_after[k / rows.rows_per_block];
      last = std::max(last, rows.row_elements[q]);
    }
  for (int b = 1; b < blocks; ++b) rows.complete_after[b] = std::max(rows.complete_after[b], rows.complete_after[b - 1]);
  return rows;
}

void PetscDistribution::Rows::fill(int b) {
  if (filled[b]) return;
  filled[b] = 1;
  const int n = static_cast<int>(start.size()) - 1;
  const int from = b * rows_per_block, to = std::min(n, from + rows_per_block);
  columns[b].resize(start[to] - start[from]);
  values[b].assign(start[to] - start[from], 0.0);
  for (int k = from; k < to; ++k) {
    int* row = columns_of(k);
    int at = 0;
    for_each_coupling(k, [&](int u) { row[at++] = u; });
    std::sort(row, row + at);
  }
}

void PetscDistribution::preallocation(Rows& rows, std::vector<PetscInt>& d_nnz, std::vector<PetscInt>& o_nnz) const {
  // Each rank counts, for every unknown its elements couple, the columns they couple it with, in
  // and outside the diagonal block of the row's owner; the owner adds the counts of all ranks. A
  // row on the cut between ranks is counted by each side, so its count may exceed its columns by
  // the couplings both sides see: an upper bound there, exact elsewhere.
  const int n = static_cast<int>(row_.size());
  std::vector<PetscInt> first(ranks_ + 1, 0);
  MPI_Allgather(&owned_rows_, 1, MPIU_INT, first.data() + 1, 1, MPIU_INT, PETSC_COMM_WORLD);
  for (int r = 0; r < ranks_; ++r) first[r + 1] += first[r];
  std::vector<PetscInt> leaf_d(n, 0), leaf_o(n, 0);
  for (int k = 0; k < n; ++k) {
    const int count = rows.count(k);
    if (count == 0) continue;
    const int owner = static_cast<int>(std::upper_bound(first.begin(), first.end(), row_[k]) - first.begin()) - 1;
    PetscInt inside = 0;
    rows.for_each_coupling(k, [&](int u) { inside += row_[u] >= first[owner] && row_[u] < first[owner + 1]; });
    leaf_d[k] = inside;
    leaf_o[k] = count - inside;
  }
  d_nnz.assign(owned_rows_, 0);
  o_nnz.assign(owned_rows_, 0);
  for (auto [leaf, root] : {std::pair{&leaf_d, &d_nnz}, std::pair{&leaf_o, &o_nnz}}) {
    petsc_check(PetscSFReduceBegin(rows_sf_, MPIU_INT, leaf->data(), root->data(), MPI_SUM), "PetscSFReduce");
    petsc_check(PetscSFReduceEnd(rows_sf_, MPIU_INT, leaf->data(), root->data(), MPI_SUM), "PetscSFReduce");
  }
  for (PetscInt r = 0; r < owned_rows_; ++r) {
    d_nnz[r] = std::min(d_nnz[r], owned_rows_);
    o_nnz[r] = std::min(o_nnz[r], rows_ - owned_rows_);
  }
  long long couplings[2] = {0, 0};  // across ranks, all
  for (PetscInt r = 0; r < owned_rows_; ++r) {
    couplings[0] += o_nnz[r];
    couplings[1] += d_nnz[r] + o_nnz[r];
  }
  MPI_Allreduce(MPI_IN_PLACE, couplings, 2, MPI_LONG_LONG, MPI_SUM, PETSC_COMM_WORLD);
  off_rank_couplings_ = couplings[0];
  all_couplings_ = couplings[1];
}

void PetscDistribution::set_rows(Mat A, Rows& rows, int from_block, int to_block) const {
  // The rows this rank owns go straight into PETSc's two blocks (the columns in and outside the
  // rank's diagonal block; before the first assembly the outer block numbers its columns
  // globally) with MAT_SORTED_FULL: each row given once, its columns increasing, is copied rather
  // than searched entry by entry (0.9 → 0.2 s at 10⁶ DOFs). The rows of other ranks (at the cut)
  // travel to their owners at MatAssemblyEnd, which adds them into the preallocated room.
  PetscInt first = 0, last = 0;
  petsc_check(MatGetOwnershipRange(A, &first, &last), "MatGetOwnershipRange");
  Mat inner = A, outer = nullptr;
  PetscBool distributed = PETSC_FALSE;
  petsc_check(PetscObjectTypeCompare(reinterpret_cast<PetscObject>(A), MATMPIAIJ, &distributed), "PetscObjectTypeCompare");
  if (distributed) petsc_check(MatMPIAIJGetSeqAIJ(A, &inner, &outer, nullptr), "MatMPIAIJGetSeqAIJ");
  for (Mat block : {inner, outer})
    if (block) petsc_check(MatSetOption(block, MAT_SORTED_FULL, PETSC_TRUE), "MatSetOption");
  std::vector<std::pair<PetscInt, double>> in, out;
  std::vector<PetscInt> cols;
  std::vector<double> vals;
  const auto put = [&](Mat block, PetscInt row, std::vector<std::pair<PetscInt, double>>& entries, InsertMode mode) {
    if (entries.empty()) return;
    if (!std::is_sorted(entries.begin(), entries.end())) std::sort(entries.begin(), entries.end());
    cols.resize(entries.size());
    vals.resize(entries.size());
    for (std::size_t i = 0; i < entries.size(); ++i) std::tie(cols[i], vals[i]) = entries[i];
    petsc_check(MatSetValues(block, 1, &row, static_cast<PetscInt>(cols.size()), cols.data(), vals.data(), mode),
                "MatSetValues");
  };
  const auto release = [&rows](int block) {  // a block already in PETSc
    std::vector<int>().swap(rows.columns[block]);
    std::vector<double>().swap(rows.values[block]);
  };
  const int n = static_cast<int>(row_.size());
  for (int b = from_block; b < to_block; ++b) rows.fill(b);  // (a block no element touched: its rows are empty)
  const int end = static_cast<int>(std::min<long long>(n, static_cast<long long>(to_block) * rows.rows_per_block));
  for (int k = from_block * rows.rows_per_block; k < end; ++k) {
    if (k % rows.rows_per_block == 0 && k / rows.rows_per_block > from_block) release(k / rows.rows_per_block - 1);
    const int count = rows.count(k);
    if (count == 0) continue;
    const int* columns = rows.columns_of(k);
    const double* values = rows.values_of(k);
    const PetscInt row = row_[k];
    in.clear();
    out.clear();
    if (row < first || row >= last) {  // another rank's row: all columns, global, added at its owner
      for (int p = 0; p < count; ++p) in.emplace_back(row_[columns[p]], values[p]);
      put(A, row, in, ADD_VALUES);
      continue;
    }
    for (int p = 0; p < count; ++p) {
      const PetscInt column = row_[columns[p]];
      if (column >= first && column < last) in.emplace_back(distributed ? column - first : column, values[p]);
      else out.emplace_back(column, values[p]);
    }
    const PetscInt local = distributed ? row - first : row;
    put(inner, local, in, INSERT_VALUES);
    put(outer, local, out, INSERT_VALUES);
  }
  if (to_block > from_block) release(to_block - 1);
  for (Mat block : {inner, outer})
    if (block) petsc_check(MatSetOption(block, MAT_SORTED_FULL, PETSC_FALSE), "MatSetOption");
}

void PetscDistribution::matrix(const Formulation& f, const std::vector<FormTerm>& terms, ExtendedResidual* extended,
                               Mat& A) const {
  // The element matrices are summed here, in the rows of this rank's couplings, and each row goes
  // to PETSc in one piece (set_rows): PETSc's search of every entry's place in its row cost more
  // than computing the element matrices' double parts (2.5 s of 6 s at 10⁶ cubic B-spline DOFs).
  // The sums are PETSc's: each entry adds its elements in the same order.
  Rows couplings_of_rows;
  on_every_rank([&] { couplings_of_rows = couplings(); });
  petsc_check(MatCreate(PETSC_COMM_WORLD, &A), "MatCreate");
  petsc_check(MatSetSizes(A, owned_rows_, owned_rows_, rows_, rows_), "MatSetSizes");
  petsc_check(MatSetType(A, MATAIJ), "MatSetType");
  {
    std::vector<PetscInt> d_nnz, o_nnz;
    preallocation(couplings_of_rows, d_nnz, o_nnz);
    petsc_check(MatSeqAIJSetPreallocation(A, 0, d_nnz.data()), "MatSeqAIJSetPreallocation");
    petsc_check(MatMPIAIJSetPreallocation(A, 0, d_nnz.data(), 0, o_nnz.data()), "MatMPIAIJSetPreallocation");
  }
  petsc_check(MatSetOption(A, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_TRUE), "MatSetOption");
  petsc_check(MatSetOption(A, MAT_SYMMETRIC, PETSC_TRUE), "MatSetOption");
  petsc_check(MatSetOption(A, MAT_SPD, PETSC_TRUE), "MatSetOption");
  on_every_rank([&] {
    int handed_over = 0;  // blocks of rows in PETSc
    std::vector<int> dofs, local, order;
    Eigen::MatrixXd T;
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> K;
    // K(i, j) into the rows of `unknowns` (unknowns[order[·]] increasing): each row's places are
    // found in one walk along it.
    const auto add_rows = [&](const std::vector<int>& unknowns) {
      const int m = static_cast<int>(order.size());
      for (int a = 0; a < m; ++a) {
        const int row = unknowns[order[a]];
        const int block = row / couplings_of_rows.rows_per_block;
        if (block < handed_over)
          throw std::logic_error("PetscDistribution: an element matrix after its rows went to PETSc");
        couplings_of_rows.fill(block);
        const int* columns = couplings_of_rows.columns_of(row);
        double* values = couplings_of_rows.values_of(row);
        const int end = couplings_of_rows.count(row);
        int p = 0;
        for (int b = 0; b < m; ++b) {
          const int column = unknowns[order[b]];
          while (p < end && columns[p] != column) ++p;
          if (p == end) throw std::logic_error("PetscDistribution: an element coupling outside the preallocated rows");
          values[p] += K(order[a], order[b]);
        }
      }
    };
    // Tᵀ A T in double for the factorization; A itself, in double-double, for the residuals.
    std::vector<int> kept;
    const auto add_element = [&](int e, const std::vector<int>& element_dofs, const DoubleDoubleMatrix& A_e) {
      if (extended) extended->add(element_dofs, A_e);
      // Usually each function is an unknown or constrained (T selects): the free rows and columns
      // of A_e as they are, without the products by T.
      kept.clear();
      local.clear();
      bool selects = true;
      for (std::size_t i = 0; i < element_dofs.size() && selects; ++i) {
        const int d = element_dofs[i];
        const int first = basis_.outerIndexPtr()[d], count = basis_.outerIndexPtr()[d + 1] - first;
        if (count == 0) continue;
        selects = count == 1 && basis_.valuePtr()[first] == 1.0;
        kept.push_back(static_cast<int>(i));
        local.push_back(basis_.innerIndexPtr()[first]);
      }
      if (selects) {
        if (kept.empty()) return;
        K = A_e.hi(kept, kept);
      } else {
        element_unknowns(e, dofs, local, &T);
        if (local.empty()) return;
        // Coefficient-wise products: Eigen's blocked ones would start a thread team per element.
        K = T.transpose().lazyProduct(A_e.hi.lazyProduct(T));
      }
      order.resize(local.size());
      std::iota(order.begin(), order.end(), 0);
      if (!std::is_sorted(local.begin(), local.end()))
        std::sort(order.begin(), order.end(), [&](int a, int b) { return local[a] < local[b]; });
      add_rows(local);
    };
    // The extra terms (a shell's Nitsche terms) first: the blocks of rows go to PETSc while the
    // elements' loop runs, each once the last element adding to it is done.
    f.for_each_extra_element_matrix(mine_, add_element);
    const auto add_and_hand_over = [&](int e, const std::vector<int>& element_dofs, const DoubleDoubleMatrix& A_e) {
      add_element(e, element_dofs, A_e);
      const int position = static_cast<int>(std::lower_bound(mine_.begin(), mine_.end(), e) - mine_.begin());
      int complete = handed_over;
      while (complete < couplings_of_rows.blocks() && couplings_of_rows.complete_after[complete] <= position) ++complete;
      if (complete > handed_over) set_rows(A, couplings_of_rows, handed_over, complete);
      handed_over = complete;
    };
    for_each_element_matrix(space_, mine_, terms, f.quadrature_degree(), add_and_hand_over, components_);
    set_rows(A, couplings_of_rows, handed_over, couplings_of_rows.blocks());
    couplings_of_rows = Rows();
  });
  petsc_check(MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
  petsc_check(MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
}

Eigen::VectorXd PetscDistribution::free_values(Vec x) const {
  Eigen::VectorXd u(constraints_.free.size());
  const PetscScalar* owned = nullptr;
  petsc_check(VecGetArrayRead(x, &owned), "VecGetArrayRead");
  petsc_check(PetscSFBcastBegin(rows_sf_, MPIU_SCALAR, owned, u.data(), MPI_REPLACE), "PetscSFBcast");
  petsc_check(PetscSFBcastEnd(rows_sf_, MPIU_SCALAR, owned, u.data(), MPI_REPLACE), "PetscSFBcast");
  petsc_check(VecRestoreArrayRead(x, &owned), "VecRestoreArrayRead");
  return u;
}

std::vector<double> PetscDistribution::sum_to_owners(const std::vector<DoubleDouble>& contributions) const {
  // Every contribution travels to the row's owner (a gather: PETSc's reductions know no
  // double-double sum), which adds them with the error-free sum and rounds once.
  const PetscInt* degree = nullptr;
  petsc_check(PetscSFComputeDegreeBegin(rows_sf_, &degree), "PetscSFComputeDegree");
  petsc_check(PetscSFComputeDegreeEnd(rows_sf_, &degree), "PetscSFComputeDegree");
  const PetscInt slots = std::accumulate(degree, degree + owned_rows_, PetscInt(0));
  std::vector<double> hi(contributions.size()), lo(contributions.size()), hi_at(slots), lo_at(slots);
  for (std::size_t k = 0; k < contributions.size(); ++k) {
    hi[k] = contributions[k].hi;
    lo[k] = contributions[k].lo;
  }
  petsc_check(PetscSFGatherBegin(rows_sf_, MPI_DOUBLE, hi.data(), hi_at.data()), "PetscSFGather");
  petsc_check(PetscSFGatherEnd(rows_sf_, MPI_DOUBLE, hi.data(), hi_at.data()), "PetscSFGather");
  petsc_check(PetscSFGatherBegin(rows_sf_, MPI_DOUBLE, lo.data(), lo_at.data()), "PetscSFGather");
  petsc_check(PetscSFGatherEnd(rows_sf_, MPI_DOUBLE, lo.data(), lo_at.data()), "PetscSFGather");
  std::vector<double> out(owned_rows_);
  PetscInt slot = 0;
  for (PetscInt r = 0; r < owned_rows_; ++r) {
    DoubleDouble sum;
    for (PetscInt j = 0; j < degree[r]; ++j, ++slot) sum += DoubleDouble{hi_at[slot], lo_at[slot]};
    out[r] = sum.hi + sum.lo;
  }
  return out;
}

}  // namespace iga

#endif
