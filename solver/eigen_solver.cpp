#include "solver/eigen_solver.hpp"

#include <Eigen/CholmodSupport>
#include <Eigen/Eigenvalues>
#include <Spectra/MatOp/SparseSymMatProd.h>
#include <Spectra/SymGEigsShiftSolver.h>
#include <algorithm>
#include <cmath>
#include <numeric>

#include "config/errors.hpp"
#include "solver/blas_threads.hpp"
#include "solver/linear_solver.hpp"

namespace iga {

namespace {

/// y = (K − σM)⁻¹ x with one CHOLMOD factor: Spectra's operation interface (its own
/// SymShiftInvert would factor with SparseLU).
class CholmodShiftInvert {
 public:
  using Scalar = double;
  CholmodShiftInvert(const SparseMatrix& K, const SparseMatrix& M, EigenReport& report)
      : K_(K), M_(M), report_(report) {
    llt_.cholmod().print = 0;  // a failed factorization is reported by the caller
  }
  Eigen::Index rows() const { return K_.rows(); }
  Eigen::Index cols() const { return K_.cols(); }
  /// Factor K − σM; false when it is not positive definite.
  bool factor(double sigma) {
    const Stopwatch clock;
    if (sigma == 0.0) llt_.compute(K_);
    else llt_.compute(SparseMatrix(K_ - sigma * M_));
    report_.t_factorize += clock.seconds();
    return llt_.info() == Eigen::Success;
  }
  void set_shift(double sigma) {  // factored before (factor): Spectra calls this once
    if (sigma != report_.shift) throw std::logic_error("CholmodShiftInvert: shift changed after factorization");
  }
  void perform_op(const double* x_in, double* y_out) const {
    Eigen::Map<Eigen::VectorXd>(y_out, K_.rows()) = llt_.solve(Eigen::Map<const Eigen::VectorXd>(x_in, K_.rows()));
    ++report_.operations;
  }

 private:
  const SparseMatrix& K_;
  const SparseMatrix& M_;
  EigenReport& report_;
  Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> llt_;
};

/// Sort ascending, M-normalise, fix the signs, measure the residuals.
EigenPairs finish(Eigen::VectorXd values, Eigen::MatrixXd vectors, const SparseMatrix& K, const SparseMatrix& M,
                  EigenReport& report) {
  std::vector<int> order(values.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return values(a) < values(b); });
  EigenPairs out{Eigen::VectorXd(values.size()), Eigen::MatrixXd(vectors.rows(), values.size())};
  report.max_residual = 0;
  for (int i = 0; i < static_cast<int>(order.size()); ++i) {
    Eigen::VectorXd x = vectors.col(order[i]);
    const Eigen::VectorXd Mx = M * x;
    x /= std::sqrt(x.dot(Mx));
    Eigen::Index big;
    x.cwiseAbs().maxCoeff(&big);
    if (x(big) < 0) x = -x;
    const double lambda = values(order[i]);
    const Eigen::VectorXd Mxn = M * x;
    const double scale = std::max(std::abs(lambda), 1e-300) * Mxn.norm();
    report.max_residual = std::max(report.max_residual, (K * x - lambda * Mxn).norm() / scale);
    out.values(i) = lambda;
    out.vectors.col(i) = x;
  }
  return out;
}

}  // namespace

EigenPairs smallest_eigenpairs(const SparseMatrix& K, const SparseMatrix& M, int count, EigenReport& report) {
  const int n = static_cast<int>(K.rows());
  if (count < 1 || count >= n)
    throw InputError("eigen.count = " + std::to_string(count) + " needs more free unknowns than that (the space has " +
                     std::to_string(n) + ")");
  set_blas_threads_for(n);
  report = {};
  report.method = "spectra shift-invert lanczos + cholmod";
  CholmodShiftInvert op(K, M, report);
  if (!op.factor(0.0)) {
    // K singular (constants in its kernel): shift below the spectrum by 10⁻⁶ λ_max (λ_max about
    // max K_ii / max M_ii), so that K − σM has a condition number near 10⁶ and λ = 0 stays the
    // eigenvalue closest to σ.
    report.shift = -K.diagonal().maxCoeff() / M.diagonal().maxCoeff() * 1e-6;
    if (!op.factor(report.shift))
      throw NumericalError("eigenproblem: K − σM is not positive definite (K not semi-definite or M singular)");
  }
  Spectra::SparseSymMatProd<double> mass(M);
  // Lanczos basis: twice the wanted pairs, at least 20 (fewer restarts for clusters of multiple λ).
  const int ncv = std::min(n, std::max(2 * count + 1, count + 20));
  Spectra::SymGEigsShiftSolver<CholmodShiftInvert, Spectra::SparseSymMatProd<double>, Spectra::GEigsMode::ShiftInvert>
      solver(op, mass, count, ncv, report.shift);
  const Stopwatch clock;
  solver.init();
  // Relative tolerance of the Ritz values of (K − σM)⁻¹M: eigenvalue errors go like its square.
  solver.compute(Spectra::SortRule::LargestMagn, 1000, 1e-13);
  report.t_solve = clock.seconds();
  if (solver.info() != Spectra::CompInfo::Successful)
    throw NumericalError("eigenproblem: Lanczos did not converge for " + std::to_string(count) + " eigenpairs");
  EigenPairs out = finish(solver.eigenvalues(), solver.eigenvectors(), K, M, report);
  if (!(report.max_residual < 1e-6))
    throw NumericalError("eigenproblem: eigenpair residual " + std::to_string(report.max_residual) + " is not small");
  return out;
}

EigenPairs all_eigenpairs(const SparseMatrix& K, const SparseMatrix& M, EigenReport& report) {
  report = {};
  report.method = "dense";
  const Stopwatch clock;
  const Eigen::MatrixXd Kd(K), Md(M);
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(Kd, Md);
  report.t_solve = clock.seconds();
  if (solver.info() != Eigen::Success) throw NumericalError("eigenproblem: the dense generalized solver failed");
  return finish(solver.eigenvalues(), solver.eigenvectors(), K, M, report);
}

}  // namespace iga
