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

/// The derivatives d[a][b] = ∂^a_u ∂^b_v x, a + b ≤ nder (1 or 2; the others zero), at (u, v) of the
/// tensor-product map x = A / W from the pieces of spans (span_u, span_v): A = Σ w P N M and
/// W = Σ w N M, control points numbered i + j n_u, `weights` empty (all 1) or one per point. Without
/// `quotient` the homogeneous sums A themselves are returned (a map whose weights are all 1).
template <class Point>
std::array<std::array<Point, 3>, 3> tensor_map_derivatives(const KnotVector& knots_u, const KnotVector& knots_v,
                                                           double u, double v, int span_u, int span_v, int nder,
                                                           const std::vector<Point>& points,
                                                           const std::vector<double>& weights, bool quotient) {
  const int pu = knots_u.degree(), pv = knots_v.degree(), nu = knots_u.num_functions();
  const SpanDerivatives Nu(knots_u, span_u, u, nder);
  const SpanDerivatives Nv(knots_v, span_v, v, nder);
  // Homogeneous sums A_ab = Σ w P ∂^a N ∂^b M and W_ab = Σ w ∂^a N ∂^b M.
  std::array<std::array<Point, 3>, 3> A;
  double W[3][3];
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      A[a][b].setZero();
      W[a][b] = 0.0;
    }
  for (int jb = 0; jb <= pv; ++jb)
    for (int ia = 0; ia <= pu; ++ia) {
      const int idx = (span_u - pu + ia) + (span_v - pv + jb) * nu;
      const double w = weights.empty() ? 1.0 : weights[idx];
      const Point wp = w * points[idx];
      for (int a = 0; a <= nder; ++a)
        for (int b = 0; a + b <= nder; ++b) {
          const double s = Nu(a, ia) * Nv(b, jb);
          A[a][b] += s * wp;
          W[a][b] += s * w;
        }
    }
  if (!quotient) return A;
  // x = A / W: x_k = (A_k − W_k x) / W, x_kl = (A_kl − W_kl x − W_k x_l − W_l x_k) / W.
  std::array<std::array<Point, 3>, 3> d = A;
  const double w0 = W[0][0];
  d[0][0] = A[0][0] / w0;
  d[1][0] = (A[1][0] - W[1][0] * d[0][0]) / w0;
  d[0][1] = (A[0][1] - W[0][1] * d[0][0]) / w0;
  if (nder < 2) return d;
  d[2][0] = (A[2][0] - W[2][0] * d[0][0] - 2.0 * W[1][0] * d[1][0]) / w0;
  d[1][1] = (A[1][1] - W[1][1] * d[0][0] - W[1][0] * d[0][1] - W[0][1] * d[1][0]) / w0;
  d[0][2] = (A[0][2] - W[0][2] * d[0][0] - 2.0 * W[0][1] * d[0][1]) / w0;
  return d;
}

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
