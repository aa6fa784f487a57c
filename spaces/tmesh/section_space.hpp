#pragma once
/// @file
/// Univariate section spaces P^n_{u,v} = <1, s, ..., s^{n-2}, u(s), v(s)> of generalized splines
/// (polynomial u,v = s^{n-1}, s^n; trigonometric cos ws, sin ws; hyperbolic cosh ws, sinh ws), their
/// stable Taylor-remainder "G-basis" and their normalized generalized Bernstein basis on [0, h].
///
/// The G-basis (notes §3.1) in the local coordinate x in [0, h] is
///   phi_k = x^k / k! (k <= n-2),  phi_{n-1} = G_{n-1},  phi_n = G_n,
///   G_m(x) = sum_{i>=0} (-pi_rho)^i x^{m+2i} / (m+2i)!,
/// with pi_rho = w^2 (trig), -w^2 (hyperbolic), 0 (polynomial). It tends to the monomials as w -> 0,
/// so nothing cancels for small w h (raw cos/sin lose every digit at w h = 1e-3 for n = 5).
/// All tables here are *scaled*: derivative order d of phi_k is multiplied by h^{d-k}, which makes
/// them functions of t = x/h and of (w h) only, O(1) for every cell size.

#include <Eigen/Core>
#include <string>

namespace iga {

enum class SectionFamily { polynomial, trigonometric, hyperbolic };

/// The section space of one direction of a cell: family, n >= 2 and frequency w (unused for
/// polynomials).
struct SectionSpec {
  SectionFamily family = SectionFamily::polynomial;
  int n = 3;
  double w = 1.0;

  /// Product of the two non-polynomial characteristic roots: w^2, -w^2 or 0.
  double pi_rho() const;
  /// e.g. "trig w=1 n=3".
  std::string description() const;
  bool operator==(const SectionSpec& o) const {
    return family == o.family && n == o.n && (family == SectionFamily::polynomial || w == o.w);
  }
};

/// Scaled G-basis derivatives at t = x/h in [0, 1] (any t >= 0 is allowed):
/// out(d, k) = h^{d-k} phi_k^{(d)}(x) for d = 0..dmax, k = 0..n; shape (dmax+1) x (n+1).
/// Depends on h only through c = -pi_rho h^2.
Eigen::MatrixXd g_basis_scaled(int n, double pi_rho, double h, double t, int dmax);

/// Generalized Bernstein basis B_0..B_n of a section space on [0, h] (notes §1.2, §3.2): B_i has the
/// zeros of Property 1 (order i at 0, order n-i at h) and the B_i sum to one. Built by solving the
/// Hermite conditions in the scaled G-basis, so it is accurate for any w h > 0.
class SectionBernstein {
 public:
  /// Throws std::invalid_argument for n < 2, h <= 0, w <= 0 (non-polynomial), or trigonometric
  /// w h >= pi (the normalized B-basis degenerates there).
  SectionBernstein(const SectionSpec& spec, double h);

  int n() const { return spec_.n; }
  double h() const { return h_; }
  /// Reference derivatives at t = x/h: out(d, i) = h^d B_i^{(d)}(x); shape (dmax+1) x (n+1).
  /// Divide row d by h^d for physical derivatives.
  Eigen::MatrixXd derivatives(double t, int dmax) const;

 private:
  SectionSpec spec_;
  double h_;
  /// Coefficients in the scaled G-basis: B_i = sum_k coef_(i, k) h^{-k} phi_k; (n+1) x (n+1).
  Eigen::MatrixXd coef_;
};

}  // namespace iga
