#pragma once
/// @file
/// Univariate B-splines (Cox–de Boor), Bernstein polynomials on [0,1], and Bézier extraction:
/// on each nonzero span the p+1 active B-splines are a (p+1) x (p+1) matrix times the Bernstein
/// polynomials of the span, the matrix being computed by knot insertion.

#include <Eigen/Core>
#include <array>
#include <vector>

#include "spaces/bspline/knot_vector.hpp"

namespace iga {

/// Values and derivatives of the p+1 B-splines N_{mu-p}..N_mu nonzero on span `span` (= mu), at t.
/// The polynomial piece of span mu is used, also for t outside [t_mu, t_mu+1] (one-sided values
/// at knots are chosen by the span).
/// @return (nder+1) x (p+1): entry (k, j) = d^k/dt^k N_{mu-p+j}(t); orders above p are zero.
Eigen::MatrixXd bspline_derivatives(const KnotVector& knots, int span, double t, int nder);
/// Up to this degree bspline_derivatives and SpanDerivatives keep their scratch on the stack (a
/// geometry is evaluated at every quadrature point: heap scratch was half of its cost).
inline constexpr int kSpanStackDegree = 15;

/// The same into `out`, column-major (nder+1) x (p+1), without allocating up to kSpanStackDegree.
void bspline_derivatives(const KnotVector& knots, int span, double t, int nder, double* out);

/// bspline_derivatives held in a buffer of its own, on the stack up to kSpanStackDegree and order 2: the
/// maps under every space evaluate it at each quadrature point (the Eigen matrices and tables it
/// allocated were half of a map's evaluation). Entry (k, j) as in bspline_derivatives.
class SpanDerivatives {
 public:
  SpanDerivatives(const KnotVector& knots, int span, double t, int nder) : rows_(nder + 1) {
    const std::size_t size = static_cast<std::size_t>(rows_) * static_cast<std::size_t>(knots.degree() + 1);
    double* out = stack_.data();
    if (size > stack_.size()) {
      heap_.resize(size);
      out = heap_.data();
    }
    bspline_derivatives(knots, span, t, nder, out);
    data_ = out;
  }
  SpanDerivatives(const SpanDerivatives&) = delete;
  SpanDerivatives& operator=(const SpanDerivatives&) = delete;
  double operator()(int k, int j) const { return data_[k + j * rows_]; }

 private:
  std::array<double, 3 * (kSpanStackDegree + 1)> stack_;
  std::vector<double> heap_;
  const double* data_ = nullptr;
  int rows_;
};

/// The binomial coefficient C(n, k) in double (exact for polynomial degrees).
double binomial(int n, int k);

/// Bernstein polynomials B_i(u) = C(p,i) u^i (1-u)^(p-i), i = 0..p, and their derivatives.
/// @return (nder+1) x (p+1): entry (k, i) = d^k/du^k B_i(u); orders above p are zero.
Eigen::MatrixXd bernstein_derivatives(int degree, double u, int nder);

/// Bézier extraction operator C of nonzero span `span` (= mu), (p+1) x (p+1):
///   N_{mu-p+a}(t) = sum_i C(a, i) B_i((t - t_mu) / (t_mu+1 - t_mu))  for t in the span.
/// Computed by inserting t_mu and t_mu+1 until both have multiplicity p+1 (Boehm's algorithm on
/// the 2p+2 knots that define the active functions).
Eigen::MatrixXd bezier_extraction(const KnotVector& knots, int span);

/// bezier_extraction for every nonzero span, in the order of knots.spans().
std::vector<Eigen::MatrixXd> bezier_extractions(const KnotVector& knots);

}  // namespace iga
