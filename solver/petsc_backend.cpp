#include "solver/petsc_backend.hpp"

#include "config/errors.hpp"

#ifdef IGA_WITH_PETSC

#include <dlfcn.h>
#include <petscksp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <memory>
#include <sstream>

#include "assembly/boundary_conditions.hpp"
#include "assembly/element_subset_assembly.hpp"
#include "assembly/sparsity.hpp"
#include "solver/linear_solver.hpp"
#include "solver/petsc_extended_residual.hpp"
#include "solver/petsc_option_policy.hpp"
#include "solver/petsc_partition.hpp"
#include "solver/petsc_session.hpp"

namespace iga {

namespace {

/// PETSc's message for the error it last raised ("Input string abc has no integer value").
std::string petsc_message(PetscErrorCode code) {
  const char* text = nullptr;
  char* specific = nullptr;
  PetscErrorMessage(code, &text, &specific);
  if (specific && *specific) return specific;
  return text ? text : "error " + std::to_string(code);
}

void check(PetscErrorCode code, const char* what) {
  if (code != 0)
    throw std::runtime_error(std::string("PETSc failed in ") + what + " (error " + std::to_string(code) +
                             "): " + petsc_message(code));
}

/// While alive, a PETSc error returns its code without PETSc printing its "[0]PETSC ERROR" banner:
/// the calls made meanwhile (setting up, solving, destroying) may fail on option values, and
/// iga-run reports every failure itself, in one line with PETSc's message.
class QuietPetscErrors {
 public:
  QuietPetscErrors() { PetscPushErrorHandler(PetscReturnErrorHandler, nullptr); }
  ~QuietPetscErrors() { PetscPopErrorHandler(); }
  QuietPetscErrors(const QuietPetscErrors&) = delete;
  QuietPetscErrors& operator=(const QuietPetscErrors&) = delete;
};

/// An error PETSc raised on the options: named at solver.options when the config gave some (the
/// command line and PETSC_OPTIONS may have set the option instead; both are named).
std::string options_place(const PetscSettings& s) {
  return s.options.empty() ? std::string("PETSc options (command line or PETSC_OPTIONS)")
                           : (s.options_where.empty() ? std::string("solver.options") : s.options_where) +
                                 " (or the PETSc options of the command line or PETSC_OPTIONS)";
}

InputError options_error(const PetscSettings& s, const std::string& step, PetscErrorCode code) {
  return InputError(options_place(s) + ": " + step + ": " + petsc_message(code));
}

/// A KSP step (`name`: KSPSetUp, KSPSolve) without PETSc's banner. An error PETSc raises in it,
/// when the config gave options, comes from them (the solver of the config's own keys has no such
/// error): an input error naming solver.options ("PETSc " + `failed`). Without options it is
/// iga-run's or PETSc's failure (exit 1); out of memory while `doing` it, too.
void ksp_step(const std::function<PetscErrorCode()>& step, const char* name, const std::string& doing,
              const std::string& failed, const PetscSettings& s) {
  QuietPetscErrors quiet;
  const PetscErrorCode code = step();
  if (code == 0) return;
  if (code == PETSC_ERR_MEM) throw std::runtime_error("PETSc ran out of memory " + doing);
  if (!s.options.empty()) throw options_error(s, "PETSc " + failed, code);
  check(code, name);
}

void solve_quietly(KSP ksp, Vec b, Vec x, const PetscSettings& s, const std::string& method) {
  ksp_step([&] { return KSPSolve(ksp, b, x); }, "KSPSolve", "solving with " + method, "failed solving with " + method, s);
}

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

/// hypre keeps a global error flag that its destroy functions return: after a set-up it refused
/// (an option value it rejects only then), destroying the preconditioner fails again and PETSc's
/// KSPDestroy returns before freeing the solver and hypre's matrix. Clearing the flag first lets the
/// destroy free everything. Looked up at run time: libHYPRE is there only as PETSc's dependency (or
/// not at all), iga-run does not link it.
void clear_hypre_errors() {
  using Clear = int (*)();
  if (auto clear = reinterpret_cast<Clear>(dlsym(RTLD_DEFAULT, "HYPRE_ClearAllErrors"))) clear();
}

/// PETSc objects destroyed on every path out (PETSc's destroy functions accept null handles).
struct PetscObjects {
  Mat A = nullptr;
  Vec b = nullptr, x = nullptr, all = nullptr;
  KSP ksp = nullptr;
  VecScatter to_all = nullptr;
  ~PetscObjects() {
    // A destroy may raise an error too (hypre checks some options only then); it would print its
    // banner while the error already on its way is reported. Destroying frees what it can anyway.
    QuietPetscErrors quiet;
    VecScatterDestroy(&to_all);
    clear_hypre_errors();
    KSPDestroy(&ksp);
    VecDestroy(&all);
    VecDestroy(&x);
    VecDestroy(&b);
    MatDestroy(&A);
  }
};

/// The config's extra options (already checked by parse_config_petsc_options when the config was
/// read), each unless the command line or PETSC_OPTIONS already set it.
void insert_config_options(const std::string& options) {
  for (const PetscOption& o : parse_config_petsc_options(options)) {
    PetscBool set = PETSC_FALSE;
    check(PetscOptionsHasName(nullptr, nullptr, o.name.c_str(), &set), "PetscOptionsHasName");
    if (!set) check(PetscOptionsSetValue(nullptr, o.name.c_str(), o.value ? o.value->c_str() : nullptr), "PetscOptionsSetValue");
  }
}

void configure_ksp(KSP ksp, const PetscSettings& s, int ranks) {
  check(KSPSetType(ksp, s.ksp == "cg" ? KSPCG : s.ksp == "gmres" ? KSPGMRES : KSPPREONLY), "KSPSetType");
  PC pc;
  check(KSPGetPC(ksp, &pc), "KSPGetPC");
  if (s.pc == "gamg") {
    check(PCSetType(pc, PCGAMG), "PCSetType");
  } else if (s.pc == "hypre") {
    check(PCSetType(pc, PCHYPRE), "PCSetType");
    check(PCHYPRESetType(pc, "boomeramg"), "PCHYPRESetType");
  } else if (s.pc == "mumps" || s.pc == "cholesky") {
    check(PCSetType(pc, PCCHOLESKY), "PCSetType");
    // PETSc's own Cholesky is sequential; across ranks the factorization is MUMPS's.
    if (s.pc == "mumps" || ranks > 1) check(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS), "PCFactorSetMatSolverType");
  } else if (s.pc == "ilu") {
    check(PCSetType(pc, ranks > 1 ? PCBJACOBI : PCILU), "PCSetType");  // ILU(0) of each rank's block
  }
  check(KSPSetTolerances(ksp, s.rtol, PETSC_DEFAULT, PETSC_DEFAULT, s.max_iterations), "KSPSetTolerances");
  check(KSPSetResidualHistory(ksp, nullptr, PETSC_DECIDE, PETSC_TRUE), "KSPSetResidualHistory");
  insert_config_options(s.options);
  QuietPetscErrors quiet;
  const PetscErrorCode code = KSPSetFromOptions(ksp);  // the command line and PETSC_OPTIONS win
  if (code != 0) throw options_error(s, "PETSc refused an option", code);
}

std::string describe(KSP ksp) {
  KSPType kt;
  PC pc;
  PCType pt;
  KSPGetType(ksp, &kt);
  KSPGetPC(ksp, &pc);
  PCGetType(pc, &pt);
  std::string text = std::string(kt) + " + " + pt;
  MatSolverType solver = nullptr;
  if (PCFactorGetMatSolverType(pc, &solver) == 0 && solver) text += " (" + std::string(solver) + ")";
  return text;
}

/// Why the preconditioner failed, the same on every rank (collective): PETSc's reason, worst over
/// the ranks, and MUMPS's INFOG(1), INFOG(2) when MUMPS factored. Sets `zero_pivot` when the
/// factorization met a zero pivot, a property of the matrix as much as of the options.
std::string pc_failure(KSP ksp, bool& zero_pivot) {
  QuietPetscErrors quiet;  // PCFactorGetMatrix refuses a PC that is no factorization
  PC pc;
  KSPGetPC(ksp, &pc);
  PCFailedReason local = PC_NOERROR;
  PCGetFailedReasonRank(pc, &local);
  int worst = static_cast<int>(local);
  MPI_Allreduce(MPI_IN_PLACE, &worst, 1, MPI_INT, MPI_MAX, PetscObjectComm(reinterpret_cast<PetscObject>(ksp)));
  const auto reason = static_cast<PCFailedReason>(worst);
  zero_pivot = reason == PC_FACTOR_STRUCT_ZEROPIVOT || reason == PC_FACTOR_NUMERIC_ZEROPIVOT;
  std::string text = reason == PC_NOERROR ? std::string("PC_FAILED") : std::string(PCFailedReasons[reason]);
  MatSolverType solver = nullptr;
  Mat factor = nullptr;
  PetscInt infog1 = 0, infog2 = 0;
  if (PCFactorGetMatSolverType(pc, &solver) == 0 && solver && std::string(solver) == MATSOLVERMUMPS &&
      PCFactorGetMatrix(pc, &factor) == 0 && MatMumpsGetInfog(factor, 1, &infog1) == 0 &&
      MatMumpsGetInfog(factor, 2, &infog2) == 0 && infog1 < 0)
    text += "; MUMPS INFOG(1) = " + std::to_string(infog1) + ", INFOG(2) = " + std::to_string(infog2) +
            (infog1 == -13 ? ", an allocation failed" : "");
  return text;
}

/// "DIVERGED_ITS after 50 iterations; last residual norms 1.2e-3, 1.1e-3, 1.0e-3 (‖b‖ = 2.5)".
std::string failure_text(KSP ksp, KSPConvergedReason reason, double bnorm) {
  PetscInt its = 0, n = 0;
  const PetscReal* history = nullptr;
  KSPGetIterationNumber(ksp, &its);
  KSPGetResidualHistory(ksp, &history, &n);
  std::ostringstream out;
  out.precision(3);
  out << KSPConvergedReasons[reason] << " after " << its << " iterations";
  if (n > 0) {
    out << "; last residual norms";
    for (PetscInt i = std::max<PetscInt>(0, n - 3); i < n; ++i) out << (i > std::max<PetscInt>(0, n - 3) ? ", " : " ") << history[i];
  }
  out << " (right-hand side norm " << bnorm << ")";
  return out.str();
}

/// This rank's entries of `v` from `values`.
void set_owned(Vec v, const std::vector<double>& values) {
  PetscScalar* entries = nullptr;
  check(VecGetArray(v, &entries), "VecGetArray");
  std::copy(values.begin(), values.end(), entries);
  check(VecRestoreArray(v, &entries), "VecRestoreArray");
}

/// The whole solution x on every rank, in the distributed numbering, handed to `use`. Collective.
void with_whole_solution(PetscObjects& p, const std::function<void(const PetscScalar*)>& use) {
  check(VecScatterBegin(p.to_all, p.x, p.all, INSERT_VALUES, SCATTER_FORWARD), "VecScatterBegin");
  check(VecScatterEnd(p.to_all, p.x, p.all, INSERT_VALUES, SCATTER_FORWARD), "VecScatterEnd");
  const PetscScalar* all = nullptr;
  check(VecGetArrayRead(p.all, &all), "VecGetArrayRead");
  use(all);
  check(VecRestoreArrayRead(p.all, &all), "VecRestoreArrayRead");
}

/// Iterative refinement with the KSP's factor, the serial solver's rule (refine_iteratively):
/// corrections K⁻¹ r, r from the extended-precision residual. Returns the number of corrections
/// applied. Collective (norms and the KSP's reason are the same on every rank).
int refine_solution(PetscObjects& p, ExtendedResidual& residual, const PetscSettings& s, const std::string& method) {
  Vec r = nullptr, d = nullptr;
  check(VecDuplicate(p.x, &r), "VecDuplicate");
  check(VecDuplicate(p.x, &d), "VecDuplicate");
  PetscReal size = 0, xnorm = 0;
  check(VecNorm(p.x, NORM_2, &xnorm), "VecNorm");
  const auto correct = [&] {
    with_whole_solution(p, [&](const PetscScalar* all) { set_owned(r, residual.owned_rows(all)); });
    solve_quietly(p.ksp, r, d, s, method);
    KSPConvergedReason reason;
    check(KSPGetConvergedReason(p.ksp, &reason), "KSPGetConvergedReason");
    check(VecNorm(d, NORM_2, &size), "VecNorm");
    return reason < 0 ? std::numeric_limits<double>::quiet_NaN() : static_cast<double>(size);
  };
  const auto apply = [&] {
    check(VecAXPY(p.x, 1.0, d), "VecAXPY");
    check(VecNorm(p.x, NORM_2, &xnorm), "VecNorm");
    return static_cast<double>(xnorm);
  };
  const int steps = refine_iteratively(xnorm, correct, apply);
  VecDestroy(&d);
  VecDestroy(&r);
  return steps;
}

/// The backend of petsc_backend.hpp (its file comment says how it works).
class PetscBackend final : public LinearBackend {
 public:
  PetscBackend(const Space& space, const PetscSettings& settings, const ProgressSink& say)
      : space_(space), settings_(settings), rank_(mpi_rank()), ranks_(mpi_size()) {
    on_every_rank([&] {
      if (say)
        say("partitioning " + std::to_string(space.num_elements()) + " elements over " + std::to_string(ranks_) +
            " rank(s)");
      owner_ = partition_elements(element_centres(space), ranks_);
      for (int e = 0; e < space.num_elements(); ++e)
        if (owner_[e] == rank_) mine_.push_back(e);
    });
  }

  WorkShare share() const override {
    return {&mine_, [](double part) {
              MPI_Allreduce(MPI_IN_PLACE, &part, 1, MPI_DOUBLE, MPI_SUM, PETSC_COMM_WORLD);
              return part;
            }};
  }
  void locally(const std::function<void()>& work) const override { on_every_rank(work); }
  void assemble(const Formulation& f, const Constraints& c, const Eigen::VectorXd& load,
                const ProgressSink& say) override;
  Eigen::VectorXd solve(SolveReport& report, const ProgressSink& say) override;

 private:
  /// The distributed numbering of the unknowns under the conditions `c` (layout_, couplings_,
  /// basis_), and with `pattern` the couplings of this rank's elements' functions. Collective.
  void lay_out(const Constraints& c, SparseMatrix* pattern, const ProgressSink& say);
  /// Create `A`, the distributed matrix Σ terms on the unknowns of lay_out (Tᵀ A T in double),
  /// each element matrix also handed to `extended` in double-double when given; the caller owns
  /// `A` (and destroys it on every path). Collective. An eigensolver (SLEPc) asks it for the
  /// stiffness f.terms() and for a mass term on the same layout.
  void matrix(const Formulation& f, const std::vector<FormTerm>& terms, ExtendedResidual* extended, Mat& A) const;

  const Space& space_;
  const PetscSettings& settings_;
  const int rank_, ranks_;
  std::vector<int> owner_, mine_;
  const Constraints* constraints_ = nullptr;
  FreeBasis basis_;
  UnknownLayout layout_;
  RowCouplings couplings_;
  PetscObjects p_;
  std::unique_ptr<ExtendedResidual> extended_;
};

void PetscBackend::lay_out(const Constraints& c, SparseMatrix* pattern, const ProgressSink& say) {
  constraints_ = &c;
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

void PetscBackend::matrix(const Formulation& f, const std::vector<FormTerm>& terms, ExtendedResidual* extended,
                          Mat& A) const {
  const PetscInt n_global = static_cast<PetscInt>(constraints_->free.size());
  const PetscInt n_local = layout_.first_row[rank_ + 1] - layout_.first_row[rank_];
  check(MatCreate(PETSC_COMM_WORLD, &A), "MatCreate");
  check(MatSetSizes(A, n_local, n_local, n_global, n_global), "MatSetSizes");
  check(MatSetType(A, MATAIJ), "MatSetType");
  const std::vector<PetscInt> d_nnz(couplings_.on_rank_columns.begin(), couplings_.on_rank_columns.end());
  const std::vector<PetscInt> o_nnz(couplings_.off_rank_columns.begin(), couplings_.off_rank_columns.end());
  check(MatSeqAIJSetPreallocation(A, 0, d_nnz.data()), "MatSeqAIJSetPreallocation");
  check(MatMPIAIJSetPreallocation(A, 0, d_nnz.data(), 0, o_nnz.data()), "MatMPIAIJSetPreallocation");
  check(MatSetOption(A, MAT_SYMMETRIC, PETSC_TRUE), "MatSetOption");
  check(MatSetOption(A, MAT_SPD, PETSC_TRUE), "MatSetOption");
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
      check(MatSetValues(A, m, rows.data(), m, rows.data(), K.data(), ADD_VALUES), "MatSetValues");
    };
    for_each_element_matrix(space_, mine_, terms, f.quadrature_degree(), add_element);
  });
  check(MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
  check(MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
}

void PetscBackend::assemble(const Formulation& f, const Constraints& c, const Eigen::VectorXd& load,
                            const ProgressSink& say) {
  // With a direct factorization the solution is refined with residuals of the matrix kept in
  // double-double: the corrections reuse the factor and remove the error floor of the double
  // matrix. Krylov solves stop at their tolerance anyway (the right-hand side is exact for both).
  const bool refine = settings_.pc == "mumps" || settings_.pc == "cholesky";
  SparseMatrix pattern;
  lay_out(c, refine ? &pattern : nullptr, say);
  extended_ = std::make_unique<ExtendedResidual>(c, layout_.global, layout_.first_row, rank_, std::move(pattern));
  if (say) say("assembling (" + std::to_string(c.free.size()) + " unknowns, in extended precision)");
  on_every_rank([&] { extended_->add_load(load); });
  matrix(f, f.terms(), extended_.get(), p_.A);
  check(MatCreateVecs(p_.A, &p_.x, &p_.b), "MatCreateVecs");
  // The right-hand side Tᵀ(b − A g), rounded once from the double-double sums over the ranks.
  set_owned(p_.b, extended_->owned_rows(nullptr));
  if (!refine) extended_.reset();
}

Eigen::VectorXd PetscBackend::solve(SolveReport& report, const ProgressSink& say) {
  PetscObjects& p = p_;
  const MPI_Comm comm = PETSC_COMM_WORLD;
  Stopwatch clock;
  check(KSPCreate(comm, &p.ksp), "KSPCreate");
  check(KSPSetOperators(p.ksp, p.A, p.A), "KSPSetOperators");
  // Every rank has the same options (the command line, PETSC_OPTIONS and ~/.petscrc reach all
  // ranks from rank 0), so an option PETSc refuses fails on all ranks together.
  on_every_rank([&] { configure_ksp(p.ksp, settings_, ranks_); });
  const std::string method = describe(p.ksp);
  if (say) say("solving with PETSc " + method);
  // Options PETSc reads only when it builds the preconditioner (a factorization package that
  // cannot do this factorization, say) fail here. Not shared across ranks: a failure here may be
  // one rank's, and the others are then ended (end_ranks_after_failure).
  ksp_step([&] { return KSPSetUp(p.ksp); }, "KSPSetUp", "setting up " + method, "could not set up " + method,
           settings_);
  report.t_factorize = clock.seconds();
  clock.restart();
  solve_quietly(p.ksp, p.b, p.x, settings_, method);
  report.t_solve = clock.seconds();
  KSPConvergedReason reason;
  PetscInt its = 0;
  check(KSPGetConvergedReason(p.ksp, &reason), "KSPGetConvergedReason");
  check(KSPGetIterationNumber(p.ksp, &its), "KSPGetIterationNumber");
  PetscReal bnorm = 0, rnorm = 0;
  check(VecNorm(p.b, NORM_2, &bnorm), "VecNorm");
  if (reason == KSP_DIVERGED_PC_FAILED) {
    // The config's own solver keys are sized by the memory check; options are not, and they can
    // ask a factorization for what it cannot do (a workspace too large, parallel analysis that
    // is not installed). So with options a failed preconditioner is theirs (exit 2); only a zero
    // pivot may be the matrix's own (exit 1, naming the options as a possible cause).
    bool zero_pivot = false;
    const std::string why = "the preconditioner of PETSc " + method + " failed (" + pc_failure(p.ksp, zero_pivot) + ")";
    if (settings_.options.empty()) throw NumericalError(why + " (choose another solver.pc)");
    if (zero_pivot) throw NumericalError(why + "; " + options_place(settings_) + " may be the cause");
    throw InputError(options_place(settings_) + ": " + why + ", most likely because of these options");
  }
  if (reason < 0)
    throw NumericalError("PETSc " + method + " did not converge: " + failure_text(p.ksp, reason, bnorm) +
                         " (raise solver.rtol or solver.max_iterations, or choose another solver.pc)");
  check(VecScatterCreateToAll(p.x, &p.to_all, &p.all), "VecScatterCreateToAll");
  if (extended_) report.refinement_steps = refine_solution(p, *extended_, settings_, method);
  // The true residual ‖b − A x‖ / ‖b‖, whatever norm the KSP tested.
  Vec residual;
  check(VecDuplicate(p.b, &residual), "VecDuplicate");
  check(MatMult(p.A, p.x, residual), "MatMult");
  check(VecAYPX(residual, -1.0, p.b), "VecAYPX");
  check(VecNorm(residual, NORM_2, &rnorm), "VecNorm");
  VecDestroy(&residual);
  report.relative_residual = bnorm > 0 ? rnorm / bnorm : rnorm;
  report.method = "petsc " + method + ", " + std::to_string(its) + " iterations" +
                  (report.refinement_steps > 0 ? ", " + std::to_string(report.refinement_steps) + " refinement steps"
                                               : std::string()) +
                  (ranks_ > 1 ? ", " + std::to_string(ranks_) + " ranks" : "");

  // Every rank gets the whole solution (the space, the outputs and the error integrals need it).
  Eigen::VectorXd u_free(constraints_->free.size());
  with_whole_solution(p, [&](const PetscScalar* all) {
    for (Eigen::Index k = 0; k < u_free.size(); ++k) u_free(k) = all[layout_.global[k]];
  });
  return expand_solution(u_free, *constraints_);
}

}  // namespace

std::unique_ptr<LinearBackend> make_petsc_backend(const Space& space, const PetscSettings& settings,
                                                  const ProgressSink& progress) {
  ensure_petsc_initialised();
  return std::make_unique<PetscBackend>(space, settings, progress);
}

}  // namespace iga

#else  // built without PETSc

namespace iga {

std::unique_ptr<LinearBackend> make_petsc_backend(const Space&, const PetscSettings&, const ProgressSink&) {
  throw InputError("solver.type: petsc: this iga-run was built without PETSc");
}

}  // namespace iga

#endif
