#include "spaces/g1_4split/split_bspline.hpp"

#include <Eigen/LU>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "spaces/bspline/bspline_basis_1d.hpp"

namespace iga {

SplitBSpline::SplitBSpline(int k, int r) : k_(k), r_(r) {
  if (k < 2 || r < 0 || r > k - 1) throw std::invalid_argument("SplitBSpline: need k >= 2 and 0 <= r <= k-1");
  const int n = 3 * k + 2 - r;
  knots_.resize(n);
  int p = 0;
  for (int i = 0; i <= k; ++i) knots_(p++) = 0.0;
  for (int i = 0; i < k - r; ++i) knots_(p++) = 0.5;
  for (int i = 0; i <= k; ++i) knots_(p++) = 1.0;
  // Bernstein coefficients of each piece: interpolate at k+1 points of the half (exact: the
  // restriction is a polynomial of degree k).
  for (int piece = 0; piece < 2; ++piece) {
    Eigen::MatrixXd V(k + 1, k + 1), values(k + 1, size());
    for (int q = 0; q <= k; ++q) {
      const double s = double(q) / k;
      V.row(q) = bernstein_derivatives(k, s, 0).row(0);
      values.row(q) = derivatives(0.5 * (piece + s), 0, piece).row(0);
    }
    bernstein_[piece] = V.fullPivLu().solve(values);
  }
}

Eigen::VectorXd SplitBSpline::greville() const {
  Eigen::VectorXd g(size());
  for (int i = 0; i < size(); ++i) g(i) = knots_.segment(i + 1, k_).mean();
  return g;
}

Eigen::MatrixXd SplitBSpline::derivatives(double t, int order, int piece) const {
  const int p = k_;
  if (piece < 0) piece = t < 0.5 ? 0 : 1;
  // Knot span [U_span, U_span+1) of the piece.
  const int span = piece == 0 ? p : 2 * p - r_;
  // Derivatives of the p+1 non-zero functions N_{span-p..span} (The NURBS Book, A2.3).
  const auto& U = knots_;
  std::vector<double> left(p + 1), right(p + 1);
  Eigen::MatrixXd ndu(p + 1, p + 1);
  ndu(0, 0) = 1.0;
  for (int j = 1; j <= p; ++j) {
    left[j] = t - U(span + 1 - j);
    right[j] = U(span + j) - t;
    double saved = 0.0;
    for (int rr = 0; rr < j; ++rr) {
      ndu(j, rr) = right[rr + 1] + left[j - rr];
      const double temp = ndu(rr, j - 1) / ndu(j, rr);
      ndu(rr, j) = saved + right[rr + 1] * temp;
      saved = left[j - rr] * temp;
    }
    ndu(j, j) = saved;
  }
  const int n = std::min(order, p);
  Eigen::MatrixXd ders = Eigen::MatrixXd::Zero(order + 1, p + 1);
  for (int j = 0; j <= p; ++j) ders(0, j) = ndu(j, p);
  Eigen::MatrixXd a(2, p + 1);
  for (int rr = 0; rr <= p; ++rr) {
    int s1 = 0, s2 = 1;
    a(0, 0) = 1.0;
    for (int kk = 1; kk <= n; ++kk) {
      double d = 0.0;
      const int rk = rr - kk, pk = p - kk;
      if (rr >= kk) {
        a(s2, 0) = a(s1, 0) / ndu(pk + 1, rk);
        d = a(s2, 0) * ndu(rk, pk);
      }
      const int j1 = rk >= -1 ? 1 : -rk;
      const int j2 = (rr - 1 <= pk) ? kk - 1 : p - rr;
      for (int j = j1; j <= j2; ++j) {
        a(s2, j) = (a(s1, j) - a(s1, j - 1)) / ndu(pk + 1, rk + j);
        d += a(s2, j) * ndu(rk + j, pk);
      }
      if (rr <= pk) {
        a(s2, kk) = -a(s1, kk - 1) / ndu(pk + 1, rr);
        d += a(s2, kk) * ndu(rr, pk);
      }
      ders(kk, rr) = d;
      std::swap(s1, s2);
    }
  }
  double f = p;
  for (int kk = 1; kk <= n; ++kk) {
    ders.row(kk) *= f;
    f *= (p - kk);
  }
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(order + 1, size());
  out.middleCols(span - p, p + 1) = ders;
  return out;
}

}  // namespace iga
