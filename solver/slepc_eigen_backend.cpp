// The SLEPc eigen backend of the PETSc plugin, the eigen backend of a `solver.type: petsc` study:
// K and M assembled on the PETSc backend's distributed layout (petsc_distribution.hpp) and the
// smallest eigenpairs of K x = λ M x by SLEPc's EPS (generalized Hermitian, Krylov–Schur with
// shift-and-invert, one Cholesky factor of K − σM — CHOLMOD's on one rank, MUMPS's across ranks —
// σ and the number of pairs as in the serial path: eigen_solver.hpp). Every rank ends with the
// whole eigenvectors.
#include "config/errors.hpp"
#include "solver/petsc_runtime.hpp"

#ifdef IGA_WITH_SLEPC

#include <slepceps.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

#include "assembly/boundary_conditions.hpp"
#include "assembly/integrators.hpp"
#include "config/progress.hpp"
#include "solver/petsc_distribution.hpp"
#include "solver/petsc_session.hpp"

namespace iga {

namespace {

const auto check = petsc_check;

/// SLEPc's objects, destroyed on every path out.
struct SlepcObjects {
  Mat K = nullptr, M = nullptr;
  EPS eps = nullptr;
  Vec x = nullptr;
  ~SlepcObjects() {
    QuietPetscErrors quiet;
    VecDestroy(&x);
    EPSDestroy(&eps);
    MatDestroy(&M);
    MatDestroy(&K);
  }
};

class SlepcEigenBackend final : public EigenBackend {
 public:
  SlepcEigenBackend(const Space& space, const ProgressSink& say) : d_(space, say) {}

  WorkShare share() const override { return d_.share(); }
  void locally(const std::function<void()>& work) const override { on_every_rank(work); }

  void assemble(const Formulation& f, const Constraints& c, const Eigen::VectorXd&, const ProgressSink& say) override {
    f_ = &f;
    constraints_ = c;
    d_.lay_out(constraints_, say);
    if (say) say("assembling K and M (" + std::to_string(c.free.size()) + " unknowns, distributed)");
    d_.matrix(f, f.terms(), nullptr, p_.K);
    d_.matrix(f, {mass_integrator()}, nullptr, p_.M);
  }

  EigenPairs eigensolve(int count, EigenReport& report, const ProgressSink& say) override;
  Eigen::VectorXd spectrum(EigenReport& report) override;

 private:
  /// σ of the serial path: 0, or below the spectrum when nothing is constrained (eigen_solver.cpp).
  double shift() const;

  PetscDistribution d_;
  const Formulation* f_ = nullptr;
  Constraints constraints_;
  SlepcObjects p_;
};

double SlepcEigenBackend::shift() const {
  if (!constraints_.constrained.empty()) return 0.0;
  // −10⁻⁶ max K_ii / max M_ii, as serially: the constants are in K's kernel.
  Vec diagonal;
  PetscReal k_max = 0, m_max = 0;
  check(MatCreateVecs(p_.K, &diagonal, nullptr), "MatCreateVecs");
  check(MatGetDiagonal(p_.K, diagonal), "MatGetDiagonal");
  check(VecMax(diagonal, nullptr, &k_max), "VecMax");
  check(MatGetDiagonal(p_.M, diagonal), "MatGetDiagonal");
  check(VecMax(diagonal, nullptr, &m_max), "VecMax");
  VecDestroy(&diagonal);
  return -k_max / m_max * 1e-6;
}

EigenPairs SlepcEigenBackend::eigensolve(int count, EigenReport& report, const ProgressSink& say) {
  const int n = static_cast<int>(constraints_.free.size());
  if (count < 1 || count >= n)
    throw InputError("eigen.count = " + std::to_string(count) + " needs more free unknowns than that (the space has " +
                     std::to_string(n) + ")");
  if (say) say("eigensolve: " + std::to_string(count) + " eigenpairs of " + std::to_string(n) + " unknowns (SLEPc)");
  ProgressPhase phase("eigensolve", 0);
  report = {};
  report.shift = shift();
  // The serial path's pair count (a few more than asked for: a multiple eigenvalue at the edge of
  // the wanted set keeps all its copies) and its tolerance.
  const int wanted = std::min(n - 1, count + std::max(5, count / 4));
  const int ncv = std::min(n, std::max(2 * wanted + 1, wanted + 20));
  const MPI_Comm comm = PETSC_COMM_WORLD;
  check(EPSCreate(comm, &p_.eps), "EPSCreate");
  check(EPSSetOperators(p_.eps, p_.K, p_.M), "EPSSetOperators");
  check(EPSSetProblemType(p_.eps, EPS_GHEP), "EPSSetProblemType");
  check(EPSSetType(p_.eps, EPSKRYLOVSCHUR), "EPSSetType");
  check(EPSSetDimensions(p_.eps, wanted, ncv, PETSC_DEFAULT), "EPSSetDimensions");
  check(EPSSetTolerances(p_.eps, 1e-12, 1000), "EPSSetTolerances");
  check(EPSSetTarget(p_.eps, report.shift), "EPSSetTarget");
  check(EPSSetWhichEigenpairs(p_.eps, EPS_TARGET_MAGNITUDE), "EPSSetWhichEigenpairs");
  // Purification (one more solve per computed eigenvector, to remove components in M's kernel) is
  // for singular M; a mass matrix is positive definite. It was a fifth of the solves.
  check(EPSSetPurify(p_.eps, PETSC_FALSE), "EPSSetPurify");
  ST st;
  KSP ksp;
  PC pc;
  check(EPSGetST(p_.eps, &st), "EPSGetST");
  check(STSetType(st, STSINVERT), "STSetType");
  check(STGetKSP(st, &ksp), "STGetKSP");
  check(KSPSetType(ksp, KSPPREONLY), "KSPSetType");
  check(KSPGetPC(ksp, &pc), "KSPGetPC");
  check(PCSetType(pc, PCCHOLESKY), "PCSetType");
  // One rank: CHOLMOD (the serial path's factorization), whose triangular solves are about 1.5x
  // faster than MUMPS's in Krylov–Schur's hundred solves (docs/eigen.md); MUMPS across ranks.
  const bool one_rank = d_.ranks() == 1;
  check(PCFactorSetMatSolverType(pc, one_rank ? MATSOLVERCHOLMOD : MATSOLVERMUMPS), "PCFactorSetMatSolverType");
  {
    // Options of the command line and PETSC_OPTIONS (-eps_*, -st_*) win, as for the linear solve.
    QuietPetscErrors quiet;
    const PetscErrorCode code = EPSSetFromOptions(p_.eps);
    if (code != 0) throw InputError("PETSc options (command line or PETSC_OPTIONS): SLEPc refused an option: " +
                                    petsc_message(code));
  }
  report.method = std::string("slepc krylovschur shift-invert + ") + (one_rank ? "cholmod" : "mumps") + " cholesky" +
                  (d_.ranks() > 1 ? ", " + std::to_string(d_.ranks()) + " ranks" : std::string());
  Stopwatch clock;
  {
    QuietPetscErrors quiet;
    check(EPSSetUp(p_.eps), "EPSSetUp (the factorization of K - σM)");
  }
  report.t_factorize = clock.seconds();
  clock.restart();
  {
    QuietPetscErrors quiet;
    check(EPSSolve(p_.eps), "EPSSolve");
  }
  report.t_solve = clock.seconds();
  PetscInt converged = 0, its = 0;
  check(EPSGetConverged(p_.eps, &converged), "EPSGetConverged");
  check(EPSGetIterationNumber(p_.eps, &its), "EPSGetIterationNumber");
  report.operations = static_cast<int>(its);
  if (converged < count)
    throw NumericalError("eigenproblem: SLEPc converged " + std::to_string(converged) + " of " + std::to_string(count) +
                         " eigenpairs");
  // The smallest `count` of the pairs SLEPc returned, whole on every rank, M-normalised and signed
  // (the largest entry positive) as serially (eigen_solver.cpp). Only those are formed, checked and
  // gathered (the few more asked for against missed multiplicities are not needed any more).
  const int got = static_cast<int>(std::min<PetscInt>(converged, wanted));
  std::vector<double> all_values(got);
  for (int i = 0; i < got; ++i) {
    PetscScalar lambda = 0;
    check(EPSGetEigenvalue(p_.eps, i, &lambda, nullptr), "EPSGetEigenvalue");
    all_values[i] = lambda;
  }
  std::vector<int> order(got);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return all_values[a] < all_values[b]; });
  EigenPairs out{Eigen::VectorXd(count), Eigen::MatrixXd(constraints_.values.size(), count)};
  Constraints homogeneous = constraints_;
  homogeneous.values.setZero();
  check(MatCreateVecs(p_.K, &p_.x, nullptr), "MatCreateVecs");
  Vec Mx;
  check(VecDuplicate(p_.x, &Mx), "VecDuplicate");
  for (int i = 0; i < count; ++i) {
    check(EPSGetEigenvector(p_.eps, order[i], p_.x, nullptr), "EPSGetEigenvector");
    PetscReal error = 0;
    check(EPSComputeError(p_.eps, order[i], EPS_ERROR_BACKWARD, &error), "EPSComputeError");
    PetscScalar xMx = 0;
    check(MatMult(p_.M, p_.x, Mx), "MatMult");
    check(VecDot(p_.x, Mx, &xMx), "VecDot");
    check(VecScale(p_.x, 1.0 / std::sqrt(xMx)), "VecScale");
    // The eigensolver runs on the whole space on every rank: these are all the unknowns.
    Eigen::VectorXd x = d_.free_values(p_.x);
    Eigen::Index big;
    x.cwiseAbs().maxCoeff(&big);
    if (x(big) < 0) x = -x;
    out.values(i) = all_values[order[i]];
    out.vectors.col(i) = expand_solution(x, homogeneous);
    report.max_residual = std::max(report.max_residual, static_cast<double>(error));
  }
  VecDestroy(&Mx);
  if (!(report.max_residual < 1e-6))
    throw NumericalError("eigenproblem: eigenpair residual " + std::to_string(report.max_residual) + " is not small");
  if (say) {
    char line[200];
    std::snprintf(line, sizeof line, "eigensolve: %d restarts (factorize %.3f s, Krylov-Schur %.3f s), "
                  "largest residual %.1e", report.operations, report.t_factorize, report.t_solve, report.max_residual);
    say(line);
  }
  return out;
}

Eigen::VectorXd SlepcEigenBackend::spectrum(EigenReport& report) {
  // Whole spectra are for a few thousand unknowns: every rank assembles the whole pencil and runs
  // the serial dense solver (the same numbers on every rank).
  SerialEigenBackend serial;
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(f_->space().dimension());
  on_every_rank([&] { serial.assemble(*f_, constraints_, zero, {}); });
  return serial.spectrum(report);
}

}  // namespace

std::unique_ptr<EigenBackend> make_slepc_backend(const Space& space, const ProgressSink& progress) {
  PetscBool initialised = PETSC_FALSE;
  check(SlepcInitialized(&initialised), "SlepcInitialized");
  // PETSc runs already: SLEPc registers its packages on top of it (and leaves finalising to PETSc).
  if (!initialised) check(SlepcInitializeNoArguments(), "SlepcInitializeNoArguments");
  return std::make_unique<SlepcEigenBackend>(space, progress);
}

}  // namespace iga

#else  // a plugin built without SLEPc (iga-run refuses the config before it asks)

namespace iga {

std::unique_ptr<EigenBackend> make_slepc_backend(const Space&, const ProgressSink&) {
  throw InputError("solver.type: petsc with problem.eigen: this iga-run was built without SLEPc");
}

}  // namespace iga

#endif
