#pragma once
/// @file
/// The univariate layer of the 4-split macro-patch: B-splines of degree k on [0, 1/2, 1] with the
/// interior knot 1/2 of multiplicity k - r (class C^r there). m = 2k - r, basis N_0..N_m.
/// The face space is the tensor product; coefficient b_{i,j} (i along u) has local index
/// i + j (m + 1).

#include <Eigen/Core>

namespace iga {

class SplitBSpline {
 public:
  /// Degree k >= 2 and regularity 0 <= r <= k - 1.
  SplitBSpline(int k, int r);

  int degree() const { return k_; }
  int regularity() const { return r_; }
  /// Index of the last basis function, m = 2k - r.
  int last() const { return 2 * k_ - r_; }
  /// Number of basis functions m + 1 = 2k + 1 - r.
  int size() const { return 2 * k_ + 1 - r_; }
  /// Number of coefficients of a face, (m + 1)^2.
  int face_size() const { return size() * size(); }

  /// Values and derivatives up to order `order` (<= 2) of all N_i at t in [0,1]: (order+1) x (m+1).
  /// `piece` 0 / 1 evaluates the polynomial of [0,1/2] / [1/2,1] (also outside it, e.g. at t = 1/2
  /// from the left); -1 picks the piece containing t (the right one at t = 1/2).
  Eigen::MatrixXd derivatives(double t, int order, int piece = -1) const;

  /// Bernstein coefficients of the basis on one half: (k+1) x (m+1), column i holds N_i restricted
  /// to [0,1/2] (piece 0) or [1/2,1] (piece 1) in the Bernstein basis of degree k of that half.
  const Eigen::MatrixXd& bernstein_extraction(int piece) const { return bernstein_[piece]; }

  /// Greville abscissae (m + 1): interpolation there is exact on the spline space (Schoenberg–Whitney).
  Eigen::VectorXd greville() const;

 private:
  int k_, r_;
  Eigen::VectorXd knots_;
  Eigen::MatrixXd bernstein_[2];
};

}  // namespace iga
