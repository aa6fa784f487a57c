#include "spaces/bspline/exact_element_matrix.hpp"

#include <algorithm>
#include <array>
#include <vector>

#include "spaces/bspline/bspline_basis_1d.hpp"

namespace iga {

namespace {

using Row = std::vector<DoubleDouble>;
using Table = std::vector<Row>;

/// Bézier extraction of `span` in double-double: Boehm insertion of the span's ends until both have
/// multiplicity p+1 (the same algorithm as bezier_extraction, in double-double arithmetic).
Table extraction_dd(const KnotVector& knots, int span) {
  const int p = knots.degree();
  const std::vector<double>& U = knots.knots();
  std::vector<double> L(U.begin() + (span - p), U.begin() + (span + p + 2));
  const double a = U[span], b = U[span + 1];
  Table T(p + 1, Row(p + 1, DoubleDouble(0.0)));
  for (int r = 0; r <= p; ++r) T[r][r] = DoubleDouble(1.0);
  const auto insert = [&](double t) {
    const int n = static_cast<int>(L.size()) - p - 1;
    const int k = static_cast<int>(std::upper_bound(L.begin(), L.end(), t) - L.begin()) - 1;
    const auto alpha = [&](int j) {
      if (j <= k - p) return DoubleDouble(1.0);
      if (j >= k + 1) return DoubleDouble(0.0);
      return (DoubleDouble(t) - DoubleDouble(L[j])) / (DoubleDouble(L[j + p]) - DoubleDouble(L[j]));
    };
    Table next(p + 1, Row(n + 1, DoubleDouble(0.0)));
    for (int c = 0; c <= n; ++c) {
      const DoubleDouble keep = c < n ? alpha(c) : DoubleDouble(0.0);
      const DoubleDouble from_left = c >= 1 ? DoubleDouble(1.0) - alpha(c) : DoubleDouble(0.0);
      for (int r = 0; r <= p; ++r) {
        DoubleDouble s(0.0);
        if (c < n) s += T[r][c] * keep;
        if (c >= 1) s += T[r][c - 1] * from_left;
        next[r][c] = s;
      }
    }
    T.swap(next);
    L.insert(L.begin() + k + 1, t);
  };
  const auto count = [&](double t) { return static_cast<int>(std::count(L.begin(), L.end(), t)); };
  for (int m = count(a); m < p + 1; ++m) insert(a);
  for (int m = count(b); m < p + 1; ++m) insert(b);
  const int s = static_cast<int>(std::lower_bound(L.begin(), L.end(), a) - L.begin());
  Table out(p + 1, Row(p + 1));
  for (int r = 0; r <= p; ++r)
    for (int i = 0; i <= p; ++i) out[r][i] = T[r][s + i];
  return out;
}

/// Bernstein coefficients of the derivative of Σ c_i B_i^m: m (c_{i+1} − c_i) in degree m − 1.
Row differentiate(const Row& c) {
  const int m = static_cast<int>(c.size()) - 1;
  Row d(std::max(m, 0), DoubleDouble(0.0));
  for (int i = 0; i < m; ++i) d[i] = (c[i + 1] - c[i]) * static_cast<double>(m);
  return d;
}

/// The Gram matrix of the Bernstein polynomials of degrees m and n on [0, 1]:
/// ∫_0^1 B_i^m B_j^n = C(m,i) C(n,j) / ((m+n+1) C(m+n, i+j)).
Table bernstein_gram(int m, int n) {
  Table g(std::max(m + 1, 0), Row(std::max(n + 1, 0)));
  for (int i = 0; i <= m; ++i)
    for (int j = 0; j <= n; ++j)
      g[i][j] = DoubleDouble(binomial(m, i) * binomial(n, j)) / DoubleDouble((m + n + 1) * binomial(m + n, i + j));
  return g;
}

}  // namespace

SpanIntegrals span_integrals(const KnotVector& knots, int span) {
  const int p = knots.degree();
  const Table C = extraction_dd(knots, span);
  // derivative[k][a]: Bernstein coefficients of N_a^(k).
  std::array<Table, 3> derivative;
  for (int a = 0; a <= p; ++a) {
    Row c = C[a];
    for (int k = 0; k < 3; ++k) {
      derivative[k].push_back(c);
      c = differentiate(c);
    }
  }
  // ∫ (Σ_i x_i B_i^m)(Σ_j y_j B_j^n) = xᵀ G y: G y formed once per function c (the Gram matrix's
  // divisions once per span, not once per pair of functions).
  SpanIntegrals out;
  for (int k = 0; k < 3; ++k)
    for (int l = 0; l < 3; ++l) {
      DoubleDoubleMatrix& m = out.moment[k][l];
      m.resize(p + 1, p + 1);
      // Degrees of the k-th and l-th derivatives; below 0 (k or l above p) the loops are empty and
      // the moments zero.
      const int dm = p - k, dn = p - l;
      const Table gram = bernstein_gram(dm, dn);
      for (int c = 0; c <= p; ++c) {
        Row gy(std::max(dm + 1, 0), DoubleDouble(0.0));
        for (int i = 0; i <= dm; ++i)
          for (int j = 0; j <= dn; ++j) gy[i] += gram[i][j] * derivative[l][c][j];
        for (int a = 0; a <= p; ++a) {
          DoubleDouble sum(0.0);
          for (int i = 0; i <= dm; ++i) sum += derivative[k][a][i] * gy[i];
          m.set(a, c, sum);
        }
      }
    }
  return out;
}

}  // namespace iga
