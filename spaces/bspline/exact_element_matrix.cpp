#include "spaces/bspline/exact_element_matrix.hpp"

#include <algorithm>
#include <array>
#include <vector>

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

double binomial(int n, int k) {
  double c = 1.0;
  for (int i = 1; i <= k; ++i) c = c * (n - k + i) / i;  // exact for the small degrees used
  return c;
}

/// Bernstein coefficients of the derivative of Σ c_i B_i^m: m (c_{i+1} − c_i) in degree m − 1.
Row differentiate(const Row& c) {
  const int m = static_cast<int>(c.size()) - 1;
  Row d(std::max(m, 0), DoubleDouble(0.0));
  for (int i = 0; i < m; ++i) d[i] = (c[i + 1] - c[i]) * static_cast<double>(m);
  return d;
}

/// ∫_0^1 (Σ c_i B_i^m)(Σ d_j B_j^n) = Σ c_i d_j C(m,i) C(n,j) / ((m+n+1) C(m+n, i+j)).
DoubleDouble integrate_product(const Row& c, const Row& d) {
  const int m = static_cast<int>(c.size()) - 1, n = static_cast<int>(d.size()) - 1;
  DoubleDouble s(0.0);
  if (m < 0 || n < 0) return s;
  for (int i = 0; i <= m; ++i)
    for (int j = 0; j <= n; ++j)
      s += c[i] * d[j] *
           (DoubleDouble(binomial(m, i) * binomial(n, j)) / DoubleDouble((m + n + 1) * binomial(m + n, i + j)));
  return s;
}

/// local(a + b nu, c + d nu) = Σ_t weighted_t(a, c) v_t(b, d): every form here is symmetric, so
/// the upper triangle, mirrored (compiled twice, see exact_product in double_double.hpp).
template <bool kFma>
[[gnu::always_inline]] inline void tensor_entries(const std::vector<DoubleDoubleMatrix>& weighted,
                                                  const std::vector<const DoubleDoubleMatrix*>& v_moment,
                                                  DoubleDoubleMatrix& local) {
  const int nu = static_cast<int>(weighted.front().rows()), nv = static_cast<int>(v_moment.front()->rows());
  for (int d = 0; d < nv; ++d)
    for (int c = 0; c < nu; ++c) {
      const int j = c + d * nu;
      for (int b = 0; b < nv; ++b)
        for (int a = 0; a < nu; ++a) {
          const int i = a + b * nu;
          if (i > j) continue;
          DoubleDouble s(0.0);
          for (std::size_t t = 0; t < weighted.size(); ++t) s += multiply<kFma>(weighted[t](a, c), (*v_moment[t])(b, d));
          local.set(i, j, s);
          local.set(j, i, s);
        }
    }
}

[[gnu::target("avx2,fma")]] void tensor_entries_fma(const std::vector<DoubleDoubleMatrix>& weighted,
                                                     const std::vector<const DoubleDoubleMatrix*>& v_moment,
                                                     DoubleDoubleMatrix& local) {
  tensor_entries<true>(weighted, v_moment, local);
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
  SpanIntegrals out;
  for (int k = 0; k < 3; ++k)
    for (int l = 0; l < 3; ++l) {
      DoubleDoubleMatrix& m = out.moment[k][l];
      m.resize(p + 1, p + 1);
      for (int a = 0; a <= p; ++a)
        for (int c = 0; c <= p; ++c) m.set(a, c, integrate_product(derivative[k][a], derivative[l][c]));
    }
  return out;
}

bool tensor_element_matrix(const SpanIntegrals& u, const SpanIntegrals& v, const Eigen::Matrix2d& jacobian,
                           BilinearForm form, DoubleDoubleMatrix& local) {
  // G = J⁻¹ (∂ξ_a/∂x_i) and S = G Gᵀ in double-double from the double Jacobian.
  const DoubleDouble j00(jacobian(0, 0)), j01(jacobian(0, 1)), j10(jacobian(1, 0)), j11(jacobian(1, 1));
  const DoubleDouble det = j00 * j11 - j01 * j10;
  const DoubleDouble g[2][2] = {{j11 / det, -j01 / det}, {-j10 / det, j00 / det}};
  DoubleDouble S[2][2];
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b) S[a][b] = g[a][0] * g[b][0] + g[a][1] * g[b][1];
  const DoubleDouble area = abs(det);

  // A derivative ∂^α of N_a M_b: α = (orders in ξ, η). A form is Σ w_{αβ} ∫ ∂^α φ ∂^β ψ.
  struct Term {
    int au, av, bu, bv;
    DoubleDouble w;
  };
  std::vector<Term> terms;
  const auto order = [](int a, int b, int& ou, int& ov) {  // ∂_a ∂_b with a, b ∈ {0 (ξ), 1 (η)}
    ou = (a == 0) + (b == 0);
    ov = (a == 1) + (b == 1);
  };
  switch (form) {
    case BilinearForm::mass:
      terms.push_back({0, 0, 0, 0, DoubleDouble(1.0)});
      break;
    case BilinearForm::laplace:
      for (int a = 0; a < 2; ++a)
        for (int b = 0; b < 2; ++b) terms.push_back({a == 0, a == 1, b == 0, b == 1, S[a][b]});
      break;
    case BilinearForm::bilaplace:  // Δ = Σ_ab S_ab ∂_a ∂_b
    case BilinearForm::hessian:    // D²φ : D²ψ = Σ S_ac S_bd ∂_ab φ ∂_cd ψ
      for (int a = 0; a < 2; ++a)
        for (int b = 0; b < 2; ++b)
          for (int c = 0; c < 2; ++c)
            for (int d = 0; d < 2; ++d) {
              Term t{};
              order(a, b, t.au, t.av);
              order(c, d, t.bu, t.bv);
              t.w = form == BilinearForm::bilaplace ? S[a][b] * S[c][d] : S[a][c] * S[b][d];
              terms.push_back(t);
            }
      break;
    default:
      return false;
  }
  // Merge terms with the same derivative orders (the bilaplacian's 16 become 9).
  std::vector<Term> merged;
  for (const Term& t : terms) {
    auto same = std::find_if(merged.begin(), merged.end(), [&](const Term& m) {
      return m.au == t.au && m.av == t.av && m.bu == t.bu && m.bv == t.bv;
    });
    if (same == merged.end()) merged.push_back(t);
    else same->w += t.w;
  }
  // Drop terms whose weight is round-off of the Jacobian (an axis-aligned element's off-diagonal
  // ~1e-21): each term maps constants and linears to zero on its own, so dropping one keeps the
  // kernel, and its share of the matrix is far below double precision. The bilaplacian of a
  // rectangle keeps 4 of its 9 terms.
  DoubleDouble largest(0.0);
  for (const Term& t : merged) largest = std::max(largest, abs(t.w));
  std::erase_if(merged, [&](const Term& t) { return abs(t.w).hi <= 1e-20 * largest.hi; });
  const int nu = static_cast<int>(u.moment[0][0].rows()), nv = static_cast<int>(v.moment[0][0].rows());
  // The weight times the area goes into the u moments once per term (nu² products), so that an
  // entry costs one product per term.
  std::vector<DoubleDoubleMatrix> weighted(merged.size());
  for (std::size_t t = 0; t < merged.size(); ++t) {
    const DoubleDouble w = merged[t].w * area;
    const DoubleDoubleMatrix& m = u.moment[merged[t].au][merged[t].bu];
    weighted[t].resize(nu, nu);
    for (int c = 0; c < nu; ++c)
      for (int a = 0; a < nu; ++a) weighted[t].set(a, c, w * m(a, c));
  }
  std::vector<const DoubleDoubleMatrix*> v_moment;
  for (const Term& t : merged) v_moment.push_back(&v.moment[t.av][t.bv]);
  local.resize(nu * nv, nu * nv);
  if (cpu_has_avx2_fma())
    tensor_entries_fma(weighted, v_moment, local);
  else
    tensor_entries<false>(weighted, v_moment, local);
  return true;
}

}  // namespace iga
