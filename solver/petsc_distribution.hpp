#pragma once
/// @file
/// What the PETSc backends share (the linear solve of petsc_backend.cpp, the SLEPc eigensolve of
/// slepc_eigen_backend.cpp): this rank's elements, the free unknowns numbered in contiguous row
/// blocks agreed between the ranks, distributed matrices of any term list on that layout, and the
/// values of this rank's unknowns back from a distributed vector. Internal to the solver layer's
/// PETSc files: the only header that includes PETSc's (so it is not installed,
/// cmake/install.cmake), compiled with PETSc only.
///
/// A rank works on its part of the space (rank_part.hpp: a SpacePart whose first elements are the
/// rank's own, the others read-only neighbours) or, for the runs that still need it, on the whole
/// space, of which it assembles the elements the partition gives it. Nothing here is the size of
/// the whole space in the first case: unknowns are matched between ranks by their global function
/// numbers through PETSc star forests (PetscSF), with a directory of the functions distributed in
/// blocks over the ranks.

#include <petscmat.h>
#include <petscsf.h>

#include <functional>
#include <string>
#include <vector>

#include "solver/formulation.hpp"

namespace iga {

class ExtendedResidual;

/// PETSc's message for the error it last raised ("Input string abc has no integer value").
std::string petsc_message(PetscErrorCode code);
/// Throws std::runtime_error naming `what` and PETSc's message when `code` is an error.
void petsc_check(PetscErrorCode code, const char* what);

/// While alive, a PETSc error returns its code without PETSc printing its "[0]PETSC ERROR" banner:
/// iga-run reports every failure itself, in one line with PETSc's message.
class QuietPetscErrors {
 public:
  QuietPetscErrors() { PetscPushErrorHandler(PetscReturnErrorHandler, nullptr); }
  ~QuietPetscErrors() { PetscPopErrorHandler(); }
  QuietPetscErrors(const QuietPetscErrors&) = delete;
  QuietPetscErrors& operator=(const QuietPetscErrors&) = delete;
};

/// The distribution of one space's system over PETSC_COMM_WORLD.
class PetscDistribution {
 public:
  /// `space`: this rank's SpacePart (its own elements first), or the whole space, whose elements
  /// are then partitioned here (collective; `say` is told on every rank).
  PetscDistribution(const Space& space, const std::function<void(const std::string&)>& say);
  ~PetscDistribution();
  PetscDistribution(const PetscDistribution&) = delete;
  PetscDistribution& operator=(const PetscDistribution&) = delete;

  /// This rank's elements (numbers of `space`) and the sum over the ranks.
  WorkShare share() const;
  /// Number the free unknowns of `c` (conditions on `space`, kept as a copy): each belongs to one
  /// of the ranks whose own elements couple it (the lowest for an even global number, the highest
  /// for an odd one: a cut's rows split evenly), each rank's rows are contiguous. `components`: the
  /// unknowns per function (a shell's 3, in blocks as the serial assembler numbers them:
  /// component q of function i at q·N + i), for the conditions and every matrix after. Collective.
  void lay_out(const Constraints& c, const std::function<void(const std::string&)>& say, int components = 1);
  /// Create `A`, the distributed matrix Σ terms on the unknowns of lay_out (Tᵀ A T in double, T the
  /// free basis), symmetric positive definite, preallocated exactly; each element matrix also
  /// handed to `extended` in double-double when given. The formulation's element-local terms
  /// beyond the integrals (Formulation::for_each_extra_element_matrix) are added too. The caller
  /// destroys `A`. Collective.
  void matrix(const Formulation& f, const std::vector<FormTerm>& terms, ExtendedResidual* extended, Mat& A) const;
  /// The values of every free unknown of `space` (Constraints::free order) from `x`, a vector of
  /// the rows of lay_out (this rank's own and its neighbours'). Collective.
  Eigen::VectorXd free_values(Vec x) const;
  /// Σ over the ranks, per row this rank owns, of `contributions` (one per free unknown of
  /// `space`, in double-double), rounded once. Collective.
  std::vector<double> sum_to_owners(const std::vector<DoubleDouble>& contributions) const;

  const Constraints& constraints() const { return constraints_; }
  PetscInt rows() const { return rows_; }
  /// The whole space's number of functions (the part's are numbered within it), without the
  /// components.
  long long whole_dimension() const { return whole_dimension_; }
  long long whole_elements() const { return whole_elements_; }
  /// Matrix couplings between unknowns of different ranks, and all (from the last matrix's
  /// preallocation: an upper bound on rows at the cut).
  long long off_rank_couplings() const { return off_rank_couplings_; }
  long long all_couplings() const { return all_couplings_; }
  int ranks() const { return ranks_; }

 private:
  /// The unknowns this rank's own elements couple (sorted), and T_e with
  /// u|element = values|element + T_e u_unknowns (rows: the element's functions).
  void element_unknowns(int element, std::vector<int>& dofs, std::vector<int>& unknowns, Eigen::MatrixXd* T_e) const;
  /// The couplings of this rank's own elements, row by row, with a value each: for each free
  /// unknown of `space` (its position k in constraints().free), the unknowns its row couples,
  /// increasing (none for the unknowns no own element touches). Kept in blocks of whole rows of
  /// some tens of megabytes, each filled when the first element adds to it and released once
  /// PETSc has its rows (the element loop runs in the order of the rows, near enough): the rows
  /// and PETSc's matrix are never both whole in memory.
  struct Rows {
    std::vector<int> start;  ///< row k: entries start[k] .. start[k + 1] − 1
    int rows_per_block = 1;
    std::vector<std::vector<int>> columns;    ///< per block, from the entry of its first row; empty until filled
    std::vector<std::vector<double>> values;  ///< aligned with columns
    std::vector<char> filled;                 ///< per block
    /// Per block: the position in mine_ of the last element adding to its rows, as prefix maxima
    /// (blocks complete in order).
    std::vector<int> complete_after;
    /// What a block's columns are made from: the unknowns of each own element (CSR, positions
    /// in mine_) and, per row, the elements that touch it.
    std::vector<int> element_offsets, element_unknowns, row_first, row_elements;
    std::vector<int> mark;  ///< scratch of for_each_coupling: the visit that last took each unknown
    int visits = 0;

    int blocks() const { return static_cast<int>(columns.size()); }
    int count(int k) const { return start[k + 1] - start[k]; }
    /// Fills block b (its columns, its values zero) if it is not yet.
    void fill(int b);
    int* columns_of(int k) { return columns[k / rows_per_block].data() + offset(k); }
    const int* columns_of(int k) const { return columns[k / rows_per_block].data() + offset(k); }
    double* values_of(int k) { return values[k / rows_per_block].data() + offset(k); }
    int offset(int k) const { return start[k] - start[(k / rows_per_block) * rows_per_block]; }
    /// take(u) for each distinct unknown u that row k couples (in no particular order).
    template <class Take>
    void for_each_coupling(int k, Take&& take) {
      const int visit = ++visits;  // a new stamp per visit: no reset between passes
      for (int q = row_first[k]; q < row_first[k + 1]; ++q)
        for (int p = element_offsets[row_elements[q]]; p < element_offsets[row_elements[q] + 1]; ++p)
          if (const int u = element_unknowns[p]; mark[u] != visit) {
            mark[u] = visit;
            take(u);
          }
    }
  };
  Rows couplings() const;
  /// The rows of blocks from_block … to_block − 1 with their values into `A` (preallocated, not
  /// yet assembled); releases each block once it is in.
  void set_rows(Mat A, Rows& rows, int from_block, int to_block) const;
  /// Nonzeros of the rows this rank owns in and outside its diagonal block, from every rank's
  /// couplings (collective).
  void preallocation(Rows& rows, std::vector<PetscInt>& d_nnz, std::vector<PetscInt>& o_nnz) const;

  const Space& space_;
  const int rank_, ranks_;
  int components_ = 1;             ///< unknowns per function (lay_out)
  std::vector<int> mine_;          ///< this rank's elements
  std::vector<int> global_dofs_;   ///< function of `space` → of the whole space (empty: the same)
  long long whole_dimension_ = 0, whole_elements_ = 0;
  /// A copy: the caller's conditions may be a temporary of the assemble step (the solve and the
  /// refinement residuals read them after it returned).
  Constraints constraints_;
  Eigen::SparseMatrix<double, Eigen::RowMajor> basis_;
  std::vector<PetscInt> row_;
  PetscInt owned_rows_ = 0, rows_ = 0;
  /// Leaves: the free unknowns of `space`; roots: the rows this rank owns.
  PetscSF rows_sf_ = nullptr;
  mutable long long off_rank_couplings_ = 0, all_couplings_ = 0;
};

}  // namespace iga
