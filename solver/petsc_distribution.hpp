#pragma once
/// @file
/// What the PETSc backends share (the linear solve of petsc_backend.cpp, the SLEPc eigensolve of
/// slepc_eigen_backend.cpp): the elements partitioned over the ranks, the free unknowns laid out
/// in contiguous row blocks, distributed matrices of any term list on that layout, and the whole
/// free vector back on every rank. Internal to the solver layer's PETSc files: the only header
/// that includes PETSc's (so it is not installed, cmake/install.cmake), compiled with PETSc only.

#include <petscmat.h>

#include <functional>
#include <string>
#include <vector>

#include "solver/formulation.hpp"
#include "solver/petsc_partition.hpp"

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

/// The distribution of one space's system over PETSC_COMM_WORLD. Every rank builds the whole space
/// and computes the same partition; each assembles its own elements.
class PetscDistribution {
 public:
  /// Partitions the elements (collective; `say` is told on every rank).
  PetscDistribution(const Space& space, const std::function<void(const std::string&)>& say);

  /// This rank's elements and the sum over the ranks.
  WorkShare share() const;
  /// The distributed numbering of the free unknowns of `c` (kept as a copy), and with `pattern`
  /// the couplings of this rank's elements' functions. Collective.
  void lay_out(const Constraints& c, SparseMatrix* pattern, const std::function<void(const std::string&)>& say);
  /// Create `A`, the distributed matrix Σ terms on the unknowns of lay_out (Tᵀ A T in double, T the
  /// free basis), symmetric positive definite; each element matrix also handed to `extended` in
  /// double-double when given. The caller destroys `A`. Collective.
  void matrix(const Formulation& f, const std::vector<FormTerm>& terms, ExtendedResidual* extended, Mat& A) const;
  /// The free unknowns (in Constraints::free order) of `all`, a whole vector in the distributed
  /// numbering (a VecScatterCreateToAll copy).
  Eigen::VectorXd free_values(const PetscScalar* all) const;

  const Space& space() const { return space_; }
  const Constraints& constraints() const { return constraints_; }
  const UnknownLayout& layout() const { return layout_; }
  int rank() const { return rank_; }
  int ranks() const { return ranks_; }

 private:
  const Space& space_;
  const int rank_, ranks_;
  std::vector<int> owner_, mine_;
  /// A copy: the caller's conditions may be a temporary of the assemble step (the solve and the
  /// refinement residuals read them after it returned).
  Constraints constraints_;
  Eigen::SparseMatrix<double, Eigen::RowMajor> basis_;
  UnknownLayout layout_;
  RowCouplings couplings_;
};

}  // namespace iga
