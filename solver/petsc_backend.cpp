// The distributed linear backend of the PETSc plugin (PetscRuntime::make_linear_backend): the
// PETSc backend of the one pipeline (pipeline.hpp), distributed over the MPI ranks (one rank
// without mpirun). Each rank assembles the matrices of its elements (petsc_distribution.hpp: of
// its part of the space, or of the whole space's partition) with the serial assembler's
// double-double kernel, the essential conditions eliminated, into a distributed (MPIAIJ) matrix
// preallocated from the element couplings; keeps them in double-double for the right-hand side and
// the refinement residuals (petsc_extended_residual.hpp); the KSP of `settings` solves; loads,
// errors and the sums of surface problems are summed over the ranks. Written against the Space
// interface only. The KSP's failure is a NumericalError (with PETSc's reason and the last
// residual norms) on every rank; input errors found on any rank are thrown on every rank.
#include <dlfcn.h>
#include <petscksp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>

#include "assembly/assembler.hpp"
#include "assembly/boundary_conditions.hpp"
#include "config/errors.hpp"
#include "assembly/element_subset_assembly.hpp"
#include "assembly/sparsity.hpp"
#include "solver/linear_solver.hpp"
#include "solver/petsc_distribution.hpp"
#include "solver/petsc_extended_residual.hpp"
#include "solver/petsc_option_policy.hpp"
#include "solver/petsc_runtime.hpp"
#include "solver/petsc_session.hpp"

namespace iga {

namespace {

const auto check = petsc_check;

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
  Vec b = nullptr, x = nullptr;
  KSP ksp = nullptr;
  ~PetscObjects() {
    // A destroy may raise an error too (hypre checks some options only then); it would print its
    // banner while the error already on its way is reported. Destroying frees what it can anyway.
    QuietPetscErrors quiet;
    clear_hypre_errors();
    KSPDestroy(&ksp);
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
    // The graph of a spline matrix is already wide (49 couplings per row for cubics); squaring it
    // for the aggregation (PETSc's default) costs a third of the peak memory and gains nothing:
    // cubic B-splines at 10⁶ DOFs 2.32 → 1.72 GB, 24 → 17 iterations; WS4, G1, T-mesh and 4-split
    // Poisson the same or fewer iterations (-pc_gamg_square_graph 1 restores it). An option, not
    // PCGAMGSetSquareGraph: Debian's PETSc 3.18 declares that function but does not export it.
    PetscBool set = PETSC_FALSE;
    check(PetscOptionsHasName(nullptr, nullptr, "-pc_gamg_square_graph", &set), "PetscOptionsHasName");
    if (!set) check(PetscOptionsSetValue(nullptr, "-pc_gamg_square_graph", "0"), "PetscOptionsSetValue");
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

/// Iterative refinement with the KSP's factor, the serial solver's rule (refine_iteratively):
/// corrections K⁻¹ r, r from the extended-precision residual. Returns the number of corrections
/// applied. Collective (norms and the KSP's reason are the same on every rank).
int refine_solution(PetscObjects& p, const PetscDistribution& layout, ExtendedResidual& residual,
                    const PetscSettings& s, const std::string& method) {
  Vec r = nullptr, d = nullptr;
  check(VecDuplicate(p.x, &r), "VecDuplicate");
  check(VecDuplicate(p.x, &d), "VecDuplicate");
  PetscReal size = 0, xnorm = 0;
  check(VecNorm(p.x, NORM_2, &xnorm), "VecNorm");
  const auto correct = [&] {
    const Eigen::VectorXd u = layout.free_values(p.x);
    set_owned(r, residual.owned_rows(&u));
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

/// The backend of this file (its file comment says how it works).
class PetscBackend final : public LinearBackend {
 public:
  PetscBackend(const Space& space, const PetscSettings& settings, const ProgressSink& say)
      : settings_(settings), d_(space, say) {}

  WorkShare share() const override { return d_.share(); }
  void locally(const std::function<void()>& work) const override { on_every_rank(work); }
  void assemble(const Formulation& f, const Constraints& c, const Eigen::VectorXd& load,
                const ProgressSink& say) override;
  Eigen::VectorXd solve(SolveReport& report, const ProgressSink& say) override;
  /// a(u, u) from the matrix kept in double-double for the refinement (direct factorizations only;
  /// a Krylov solve keeps no unreduced matrix): each rank's elements' part, summed over the ranks.
  std::optional<double> energy(const Eigen::VectorXd& u) const override;
  void count_whole(const Formulation& f, LevelResult& r) const override {
    r.dofs = static_cast<int>(d_.whole_dimension()) * f.components();
    r.elements = static_cast<int>(d_.whole_elements());
    r.free_dofs = static_cast<int>(d_.rows());
  }

 private:
  const PetscSettings& settings_;
  PetscDistribution d_;
  PetscObjects p_;
  std::unique_ptr<ExtendedResidual> extended_;
};

void PetscBackend::assemble(const Formulation& f, const Constraints& c, const Eigen::VectorXd& load,
                            const ProgressSink& say) {
  // With a direct factorization the solution is refined with residuals of the matrix kept in
  // double-double: the corrections reuse the factor and remove the error floor of the double
  // matrix. Krylov solves stop at their tolerance anyway (the right-hand side is exact for both).
  const bool refine = settings_.pc == "mumps" || settings_.pc == "cholesky";
  const int components = f.components();  // a shell's three displacement components, in blocks
  d_.lay_out(c, say, components);
  SparseMatrix pattern;
  if (refine)
    on_every_rank([&] {
      const int n = f.space().dimension();
      pattern = sparsity_pattern(component_dofs(collect_element_dofs(f.space(), d_.share().elements), components, n),
                                 components * n);
    });
  extended_ = std::make_unique<ExtendedResidual>(d_, std::move(pattern));
  if (say) say("assembling (" + std::to_string(d_.rows()) + " unknowns, in extended precision)");
  on_every_rank([&] { extended_->add_load(load); });
  d_.matrix(f, f.terms(), extended_.get(), p_.A);
  if (d_.ranks() > 1 && say) {
    char share[32];
    std::snprintf(share, sizeof share, "%.3g %%", 100.0 * static_cast<double>(d_.off_rank_couplings()) /
                                                       static_cast<double>(std::max(1LL, d_.all_couplings())));
    say("matrix couplings between ranks: " + std::to_string(d_.off_rank_couplings()) + " of " +
        std::to_string(d_.all_couplings()) + " (" + share + ", counted from the preallocation)");
  }
  check(MatCreateVecs(p_.A, &p_.x, &p_.b), "MatCreateVecs");
  // The right-hand side Tᵀ(b − A g), rounded once from the double-double sums over the ranks.
  set_owned(p_.b, extended_->owned_rows(nullptr));
  if (!refine) extended_.reset();
}

std::optional<double> PetscBackend::energy(const Eigen::VectorXd& u) const {
  if (!extended_) return std::nullopt;
  const DoubleDouble part = extended_->energy_part(u);
  double sum[2] = {part.hi, part.lo};
  MPI_Allreduce(MPI_IN_PLACE, sum, 2, MPI_DOUBLE, MPI_SUM, PETSC_COMM_WORLD);
  return sum[0] + sum[1];
}

Eigen::VectorXd PetscBackend::solve(SolveReport& report, const ProgressSink& say) {
  PetscObjects& p = p_;
  const MPI_Comm comm = PETSC_COMM_WORLD;
  Stopwatch clock;
  check(KSPCreate(comm, &p.ksp), "KSPCreate");
  check(KSPSetOperators(p.ksp, p.A, p.A), "KSPSetOperators");
  // Every rank has the same options (the command line, PETSC_OPTIONS and ~/.petscrc reach all
  // ranks from rank 0), so an option PETSc refuses fails on all ranks together.
  on_every_rank([&] { configure_ksp(p.ksp, settings_, d_.ranks()); });
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
  if (extended_) report.refinement_steps = refine_solution(p, d_, *extended_, settings_, method);
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
                  (d_.ranks() > 1 ? ", " + std::to_string(d_.ranks()) + " ranks" : "");

  // Every rank gets the coefficients of its space (its part: its own elements and neighbours').
  return expand_solution(d_.free_values(p.x), d_.constraints());
}

}  // namespace

std::unique_ptr<LinearBackend> make_distributed_backend(const Space& space, const PetscSettings& settings,
                                                        const ProgressSink& progress) {
  return std::make_unique<PetscBackend>(space, settings, progress);
}

}  // namespace iga
