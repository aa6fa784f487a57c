#pragma once
/// @file
/// Univariate B-splines (Cox–de Boor), Bernstein polynomials on [0,1], and Bézier extraction:
/// on each nonzero span the p+1 active B-splines are a (p+1) x (p+1) matrix times the Bernstein
/// polynomials of the span, the matrix being computed by knot insertion.

#include <Eigen/Core>
#include <vector>

#include "spaces/bspline/knot_vector.hpp"

namespace iga {

/// Values and derivatives of the p+1 B-splines N_{mu-p}..N_mu nonzero on span `span` (= mu), at t.
/// The polynomial piece of span mu is used, also for t outside [t_mu, t_mu+1] (one-sided values
/// at knots are chosen by the span).
/// @return (nder+1) x (p+1): entry (k, j) = d^k/dt^k N_{mu-p+j}(t); orders above p are zero.
Eigen::MatrixXd bspline_derivatives(const KnotVector& knots, int span, double t, int nder);

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
