#include "solver/eigen_solver.hpp"

#include <Eigen/CholmodSupport>
#include <Eigen/Eigenvalues>
#include <Spectra/SymEigsSolver.h>
#include <algorithm>
#include <cmath>
#include <numeric>

#include "config/errors.hpp"
#include "solver/blas_threads.hpp"
#include "solver/linear_solver.hpp"

namespace iga {

namespace {

/// The CHOLMOD factor P (K − σM) Pᵀ = L Lᵀ (Eigen's wrapper, opened for the triangular solves).
class CholeskyFactor : public Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> {
 public:
  CholeskyFactor() { cholmod().print = 0; }  // a failed factorization is reported by the caller
  /// x = A⁻¹ b for one of CHOLMOD's systems (CHOLMOD_L, CHOLMOD_Lt, CHOLMOD_P, CHOLMOD_Pt).
  void apply(int system, const double* b, double* x) const {
    Eigen::Map<const Eigen::VectorXd> in(b, rows());
    Eigen::VectorXd copy = in;
    cholmod_dense B = Eigen::viewAsCholmod(copy);
    cholmod_dense* X = cholmod_solve(system, m_cholmodFactor, &B, &const_cast<CholeskyFactor*>(this)->cholmod());
    if (!X) throw NumericalError("eigenproblem: CHOLMOD could not solve with its factor");
    Eigen::Map<Eigen::VectorXd>(x, rows()) = Eigen::Map<const Eigen::VectorXd>(static_cast<double*>(X->x), rows());
    cholmod_free_dense(&X, &const_cast<CholeskyFactor*>(this)->cholmod());
  }
};

/// C = L⁻¹ P M Pᵀ L⁻ᵀ, symmetric, with eigenvalues ν = 1 / (λ − σ) for the pairs of K x = λ M x
/// (y = Lᵀ P x): shift-and-invert as a standard problem, so that Lanczos orthogonalizes in the
/// Euclidean inner product and each step costs one solve with the factor and one product with M
/// (in M's inner product, as Spectra's SymGEigsShiftSolver does it, the products with M took more
/// time than the solves).
class TransformedPencil {
 public:
  using Scalar = double;
  TransformedPencil(const CholeskyFactor& factor, const SparseMatrix& M, EigenReport& report)
      : factor_(factor), M_(M), report_(report), a_(M.rows()), b_(M.rows()) {}
  Eigen::Index rows() const { return M_.rows(); }
  Eigen::Index cols() const { return M_.cols(); }
  void perform_op(const double* y, double* out) const {
    factor_.apply(CHOLMOD_Lt, y, a_.data());
    factor_.apply(CHOLMOD_Pt, a_.data(), b_.data());
    a_.noalias() = M_ * b_;
    factor_.apply(CHOLMOD_P, a_.data(), b_.data());
    factor_.apply(CHOLMOD_L, b_.data(), out);
    ++report_.operations;
  }
  /// x = Pᵀ L⁻ᵀ y: the eigenvector of the pencil.
  Eigen::VectorXd pencil_vector(const Eigen::VectorXd& y) const {
    Eigen::VectorXd z(y.size()), x(y.size());
    factor_.apply(CHOLMOD_Lt, y.data(), z.data());
    factor_.apply(CHOLMOD_Pt, z.data(), x.data());
    return x;
  }

 private:
  const CholeskyFactor& factor_;
  Eigen::SparseMatrix<double, Eigen::RowMajor> M_;  // row-major: Eigen's product runs in parallel
  EigenReport& report_;
  mutable Eigen::VectorXd a_, b_;
};

/// Sort ascending, M-normalise, fix the signs, measure the residuals.
EigenPairs finish(Eigen::VectorXd values, Eigen::MatrixXd vectors, const SparseMatrix& K, const SparseMatrix& M,
                  EigenReport& report) {
  std::vector<int> order(values.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return values(a) < values(b); });
  EigenPairs out{Eigen::VectorXd(values.size()), Eigen::MatrixXd(vectors.rows(), values.size())};
  report.max_residual = 0;
  // Normwise backward error ‖Kx − λMx‖ / ((‖K‖ + |λ| ‖M‖) ‖x‖), with ∞-norms of the matrices: also
  // meaningful for λ = 0.
  const auto inf_norm = [](const SparseMatrix& A) {  // symmetric: the largest column sum
    double n = 0;
    for (int k = 0; k < A.outerSize(); ++k) {
      double s = 0;
      for (SparseMatrix::InnerIterator it(A, k); it; ++it) s += std::abs(it.value());
      n = std::max(n, s);
    }
    return n;
  };
  const double k_norm = inf_norm(K), m_norm = inf_norm(M);
  for (int i = 0; i < static_cast<int>(order.size()); ++i) {
    Eigen::VectorXd x = vectors.col(order[i]);
    const Eigen::VectorXd Mx = M * x;
    x /= std::sqrt(x.dot(Mx));
    Eigen::Index big;
    x.cwiseAbs().maxCoeff(&big);
    if (x(big) < 0) x = -x;
    const double lambda = values(order[i]);
    const double scale = (k_norm + std::abs(lambda) * m_norm) * x.norm();
    report.max_residual = std::max(report.max_residual, (K * x - lambda * (M * x)).norm() / scale);
    out.values(i) = lambda;
    out.vectors.col(i) = x;
  }
  return out;
}

}  // namespace

EigenPairs smallest_eigenpairs(const SparseMatrix& K, const SparseMatrix& M, int count, EigenReport& report,
                               bool may_be_singular) {
  const int n = static_cast<int>(K.rows());
  if (count < 1 || count >= n)
    throw InputError("eigen.count = " + std::to_string(count) + " needs more free unknowns than that (the space has " +
                     std::to_string(n) + ")");
  set_blas_threads_for(n);
  report = {};
  report.method = "spectra shift-invert lanczos + cholmod";
  CholeskyFactor factor;
  const auto factor_at = [&](double sigma) {
    const Stopwatch clock;
    if (sigma == 0.0) factor.compute(K);
    else factor.compute(SparseMatrix(K - sigma * M));
    report.t_factorize += clock.seconds();
    return factor.info() == Eigen::Success;
  };
  if (may_be_singular || !factor_at(0.0)) {
    // K singular (constants in its kernel): shift below the spectrum by 10⁻⁶ λ_max (λ_max about
    // max K_ii / max M_ii). Then K − σM has a condition number near 10⁶, and the kernel's Ritz
    // value ν₀ = 1/|σ| is not so large that orthogonalizing against it spoils the others (ε ν₀/ν:
    // at 10⁻⁸ λ_max the sphere's pairs lost 2e-10); λ = σ + 1/ν loses digits only where λ < |σ|.
    report.shift = -K.diagonal().maxCoeff() / M.diagonal().maxCoeff() * 1e-6;
    if (!factor_at(report.shift))
      throw NumericalError("eigenproblem: K − σM is not positive definite (K not semi-definite or M singular)");
  }
  // The Lanczos steps solve with one vector at a time: small, memory-bound BLAS calls that threads
  // only slow down (the factorization above used them).
  set_blas_threads_for(0);
  TransformedPencil op(factor, M, report);
  // A few more pairs than asked for: single-vector Lanczos may miss a copy of a multiple eigenvalue
  // at the edge of the wanted set (the sphere's fivefold λ = 6 as pairs 5 to 9 of 9: one was
  // missed, λ = 12 returned instead); inside the set the rounding errors find them all. The basis:
  // twice the pairs, at least 20 more (fewer restarts).
  const int wanted = std::min(n - 1, count + std::max(5, count / 4));
  const int ncv = std::min(n, std::max(2 * wanted + 1, wanted + 20));
  Spectra::SymEigsSolver<TransformedPencil> solver(op, wanted, ncv);
  const Stopwatch clock;
  solver.init();
  // Relative tolerance of the Ritz values ν: eigenvalue errors go like its square.
  solver.compute(Spectra::SortRule::LargestAlge, 1000, 1e-12);
  report.t_solve = clock.seconds();
  if (solver.info() != Spectra::CompInfo::Successful)
    throw NumericalError("eigenproblem: Lanczos did not converge for " + std::to_string(count) + " eigenpairs");
  const Eigen::VectorXd nu = solver.eigenvalues();
  const Eigen::MatrixXd y = solver.eigenvectors();
  Eigen::VectorXd lambda(nu.size());
  Eigen::MatrixXd x(n, nu.size());
  for (int i = 0; i < nu.size(); ++i) {
    lambda(i) = report.shift + 1.0 / nu(i);
    x.col(i) = op.pencil_vector(y.col(i));
  }
  EigenPairs out = finish(lambda, x, K, M, report);
  out.values.conservativeResize(count);
  out.vectors.conservativeResize(Eigen::NoChange, count);
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
