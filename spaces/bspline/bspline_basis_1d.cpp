#include "spaces/bspline/bspline_basis_1d.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>

namespace iga {

namespace {

/// Values of the nonzero B-splines of every degree q = 0..p at t on span mu, into `table` (row q
/// at q(q+1)/2): table[q][j] = N_{mu-q+j, q}(t), j = 0..q (triangular Cox–de Boor recursion).
void cox_de_boor_table(const std::vector<double>& U, int p, int mu, double t, double* table) {
  table[0] = 1.0;
  for (int q = 1; q <= p; ++q) {
    const double* below = table + (q - 1) * q / 2;
    double* row = table + q * (q + 1) / 2;
    for (int j = 0; j <= q; ++j) {
      const int i = mu - q + j;
      double v = 0.0;
      // Both denominators are > 0 here: they span the nonzero interval [t_mu, t_mu+1].
      if (j >= 1) v += (t - U[i]) / (U[i + q] - U[i]) * below[j - 1];
      if (j <= q - 1) v += (U[i + q + 1] - t) / (U[i + q + 1] - U[i + 1]) * below[j];
      row[j] = v;
    }
  }
}

}  // namespace

double binomial(int n, int k) {
  double c = 1.0;
  for (int i = 1; i <= k; ++i) c = c * (n - k + i) / i;  // exact for the small degrees used
  return c;
}

void bspline_derivatives(const KnotVector& knots, int span, double t, int nder, double* out) {
  const int p = knots.degree();
  const int mu = span;
  const std::vector<double>& U = knots.knots();
  if (mu < p || mu >= knots.num_functions() || !(U[mu] < U[mu + 1]))
    throw std::invalid_argument("bspline_derivatives: not a nonzero span");
  // The Cox–de Boor table and two coefficient rows: on the stack up to kSpanStackDegree.
  std::array<double, (kSpanStackDegree + 1) * (kSpanStackDegree + 2) / 2 + 2 * (kSpanStackDegree + 1)> stack;
  std::vector<double> heap;
  double* table = stack.data();
  if (p > kSpanStackDegree) {
    heap.resize((p + 1) * (p + 2) / 2 + 2 * (p + 1));
    table = heap.data();
  }
  double* c = table + (p + 1) * (p + 2) / 2;
  double* next = c + (p + 1);
  cox_de_boor_table(U, p, mu, t, table);
  const int rows = nder + 1;
  std::fill(out, out + rows * (p + 1), 0.0);
  const double* top = table + p * (p + 1) / 2;
  for (int j = 0; j <= p; ++j) out[j * rows] = top[j];

  // d/dt sum_m c_m N_{m,q} = sum_m q (c_m - c_{m-1}) / (t_{m+q} - t_m) N_{m,q-1}; repeat k times
  // starting from N_i itself, then evaluate with the degree p-k row of the table.
  for (int a = 0; a <= p; ++a) {
    const int i = mu - p + a;
    c[0] = 1.0;  // coefficients of N_{i..i+k, p-k}
    for (int k = 1; k <= std::min(nder, p); ++k) {
      const int q = p - k + 1;  // degree before this differentiation
      for (int r = 0; r <= k; ++r) {
        const int m = i + r;
        const double cm = r < k ? c[r] : 0.0;
        const double cm1 = r > 0 ? c[r - 1] : 0.0;
        const double h = U[m + q] - U[m];
        // h == 0 means N_{m,q-1} vanishes identically: drop it.
        next[r] = h > 0.0 ? q * (cm - cm1) / h : 0.0;
      }
      std::copy(next, next + k + 1, c);
      const int qk = p - k;
      const double* row = table + qk * (qk + 1) / 2;
      double v = 0.0;
      for (int r = 0; r <= k; ++r) {
        const int j = i + r - (mu - qk);  // position of N_{i+r, qk} in the table row
        if (j >= 0 && j <= qk) v += c[r] * row[j];
      }
      out[k + a * rows] = v;
    }
  }
}

Eigen::MatrixXd bspline_derivatives(const KnotVector& knots, int span, double t, int nder) {
  Eigen::MatrixXd out(nder + 1, knots.degree() + 1);
  bspline_derivatives(knots, span, t, nder, out.data());
  return out;
}

Eigen::MatrixXd bernstein_derivatives(int degree, double u, int nder) {
  const int p = degree;
  if (p < 0) throw std::invalid_argument("bernstein_derivatives: degree must be >= 0");
  // table[q][j] = B_j^q(u), by B_j^q = (1-u) B_j^{q-1} + u B_{j-1}^{q-1}.
  std::vector<std::vector<double>> table(p + 1);
  table[0] = {1.0};
  for (int q = 1; q <= p; ++q) {
    table[q].assign(q + 1, 0.0);
    for (int j = 0; j <= q; ++j) {
      if (j <= q - 1) table[q][j] += (1.0 - u) * table[q - 1][j];
      if (j >= 1) table[q][j] += u * table[q - 1][j - 1];
    }
  }
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(nder + 1, p + 1);
  for (int i = 0; i <= p; ++i) out(0, i) = table[p][i];
  // d^k B_i^p = p!/(p-k)! sum_j (-1)^j C(k,j) B_{i-k+j}^{p-k}  (k-fold forward difference).
  double factor = 1.0;
  for (int k = 1; k <= std::min(nder, p); ++k) {
    factor *= p - k + 1;
    const int q = p - k;
    for (int i = 0; i <= p; ++i) {
      double v = 0.0;
      for (int j = 0; j <= k; ++j) {
        const int idx = i - k + j;
        if (idx < 0 || idx > q) continue;
        v += ((j % 2) ? -1.0 : 1.0) * binomial(k, j) * table[q][idx];
      }
      out(k, i) = factor * v;
    }
  }
  return out;
}

namespace {

/// Insert t once into the local knot vector L (degree p) and update T, whose columns are the
/// coefficients of the tracked functions in the B-splines of L: N = T M before, T A after, with
/// N_j = alpha_j M'_j + (1 - alpha_{j+1}) M'_{j+1} (Boehm).
void insert_knot(std::vector<double>& L, int p, double t, Eigen::MatrixXd& T) {
  const int n = static_cast<int>(L.size()) - p - 1;  // functions before insertion
  const int k = static_cast<int>(std::upper_bound(L.begin(), L.end(), t) - L.begin()) - 1;
  auto alpha = [&](int j) {
    if (j <= k - p) return 1.0;
    if (j >= k + 1) return 0.0;
    return (t - L[j]) / (L[j + p] - L[j]);  // L[j+p] >= L[k+1] > t >= L[j]
  };
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n + 1);
  for (int j = 0; j < n; ++j) {
    A(j, j) = alpha(j);
    A(j, j + 1) = 1.0 - alpha(j + 1);
  }
  T = T * A;
  L.insert(L.begin() + k + 1, t);
}

}  // namespace

Eigen::MatrixXd bezier_extraction(const KnotVector& knots, int span) {
  const int p = knots.degree();
  const int mu = span;
  const std::vector<double>& U = knots.knots();
  if (mu < p || mu >= knots.num_functions() || !(U[mu] < U[mu + 1]))
    throw std::invalid_argument("bezier_extraction: not a nonzero span");
  // The active functions N_{mu-p..mu} only depend on these 2p+2 knots.
  std::vector<double> L(U.begin() + (mu - p), U.begin() + (mu + p + 2));
  const double a = U[mu], b = U[mu + 1];
  Eigen::MatrixXd T = Eigen::MatrixXd::Identity(p + 1, p + 1);
  auto count = [&](double t) { return static_cast<int>(std::count(L.begin(), L.end(), t)); };
  for (int m = count(a); m < p + 1; ++m) insert_knot(L, p, a, T);
  for (int m = count(b); m < p + 1; ++m) insert_knot(L, p, b, T);
  // With a and b of multiplicity p+1, the functions on knots a^(p+1-i) b^(i+1) are the Bernstein
  // polynomials of [a, b]; every other refined function vanishes on the span.
  const int s = static_cast<int>(std::lower_bound(L.begin(), L.end(), a) - L.begin());
  return T.middleCols(s, p + 1);
}

std::vector<Eigen::MatrixXd> bezier_extractions(const KnotVector& knots) {
  std::vector<Eigen::MatrixXd> out;
  out.reserve(knots.spans().size());
  for (int mu : knots.spans()) out.push_back(bezier_extraction(knots, mu));
  return out;
}

}  // namespace iga
