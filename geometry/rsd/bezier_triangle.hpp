#pragma once
/// @file
/// A polynomial triangle patch F: T̂ → R³ in Bernstein–Bézier form over barycentric coordinates
/// t = (t1, t2, t3) of a mesh triangle (t_a = 1 at its a-th vertex in mesh order):
///   F(t) = Σ_{|α| = D} b_α B^D_α(t),   B^D_α = D!/(α1! α2! α3!) t1^α1 t2^α2 t3^α3.
/// Control points are stored in the order of bezier_index.

#include <Eigen/Core>
#include <array>
#include <vector>

namespace iga {

/// Position of the multi-index (a1, a2, D − a1 − a2) in a patch of degree D: a1 = D, D−1, ..., 0
/// and, for each a1, a2 = D − a1, ..., 0 (so the vertex points come at 0, D and the last index).
int bezier_index(int degree, int a1, int a2);

/// Number of control points of a degree-D triangle patch, (D+1)(D+2)/2.
inline int bezier_count(int degree) { return (degree + 1) * (degree + 2) / 2; }

/// A triangular Bézier patch in R³.
struct BezierTriangle {
  int degree = 0;
  std::vector<Eigen::Vector3d> control;  ///< bezier_count(degree) points, bezier_index order

  /// F(t) for barycentric t (t need not sum to one: the form is homogeneous).
  Eigen::Vector3d value(const Eigen::Vector3d& t) const;
  /// The three partial derivatives ∂F/∂t_a of the homogeneous form.
  std::array<Eigen::Vector3d, 3> partials(const Eigen::Vector3d& t) const;
  /// Directional derivative Σ_a dt_a ∂F/∂t_a (dt sums to zero for a direction in the triangle).
  Eigen::Vector3d derivative(const Eigen::Vector3d& t, const Eigen::Vector3d& dt) const;
  /// The same patch written with degree `degree + 1` (exact degree elevation).
  BezierTriangle elevated() const;
};

/// Collects a vector polynomial Σ c·t^α in monomials of the barycentrics (terms of any total
/// degree ≤ D, homogenised with (t1+t2+t3)^(D−|α|)) and converts it to Bernstein form.
class BarycentricPolynomial {
 public:
  explicit BarycentricPolynomial(int degree);
  /// Adds coefficient·t1^a[0]·t2^a[1]·t3^a[2].
  void add(const std::array<int, 3>& a, const Eigen::Vector3d& coefficient);
  BezierTriangle bernstein() const;

 private:
  int degree_;
  std::vector<Eigen::Vector3d> monomial_;  // homogeneous degree-D coefficients, bezier_index order
};

}  // namespace iga
