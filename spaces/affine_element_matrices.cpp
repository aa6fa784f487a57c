#include "spaces/affine_element_matrices.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <type_traits>
#include <vector>

#include "config/cpu_dispatch.hpp"

namespace iga {

template <class Scalar>
AffineTerms<Scalar> affine_form_terms(BilinearForm form, const Eigen::Matrix2d& jacobian) {
  AffineTerms<Scalar> out;
  const auto add = [&out](int alpha, int beta, const Scalar& weight) {
    if (weight != Scalar(0.0)) out.term[out.size++] = {alpha, beta, weight};
  };
  if constexpr (std::is_same_v<Scalar, DoubleDouble>) {
    using dd_detail::two_prod;
    const Eigen::Matrix2d& j = jacobian;
    // det J exactly, and M = adj(J) adj(J)ᵀ = det² J⁻¹J⁻ᵀ (entries of adj(J) are entries of J).
    const DoubleDouble area = abs(two_prod(j(0, 0), j(1, 1)) - two_prod(j(0, 1), j(1, 0)));
    const DoubleDouble m00 = two_prod(j(1, 1), j(1, 1)) + two_prod(j(0, 1), j(0, 1));
    const DoubleDouble m01 = -(two_prod(j(1, 1), j(1, 0)) + two_prod(j(0, 1), j(0, 0)));
    const DoubleDouble m11 = two_prod(j(1, 0), j(1, 0)) + two_prod(j(0, 0), j(0, 0));
    const DoubleDouble m[2][2] = {{m00, m01}, {m01, m11}};
    const DoubleDouble cube = area * area * area;
    switch (form) {
      case BilinearForm::mass:
        add(kValue, kValue, area);
        break;
      case BilinearForm::laplace:  // |det| G_ab = M_ab / |det|
        for (int a = 0; a < 2; ++a)
          for (int b = 0; b < 2; ++b) add(kDxi + a, kDxi + b, m[a][b] / area);
        break;
      case BilinearForm::bilaplace: {  // |det| α_p α_q = β_p β_q / |det|³, β = (M00, 2 M01, M11)
        const DoubleDouble beta[3] = {m00, m01 * 2.0, m11};
        for (int p = 0; p < 3; ++p)
          for (int q = 0; q < 3; ++q) add(kDxixi + p, kDxixi + q, beta[p] * beta[q] / cube);
        break;
      }
      case BilinearForm::hessian: {  // Σ_abcd |det| G_ac G_bd ∂_ab ∂_cd = Σ M_ac M_bd / |det|³
        DoubleDouble coefficient[3][3];
        for (int a = 0; a < 2; ++a)
          for (int b = 0; b < 2; ++b)
            for (int c = 0; c < 2; ++c)
              for (int d = 0; d < 2; ++d) coefficient[a + b][c + d] += m[a][c] * m[b][d];
        for (int p = 0; p < 3; ++p)
          for (int q = 0; q < 3; ++q) add(kDxixi + p, kDxixi + q, coefficient[p][q] / cube);
        break;
      }
    }
  } else {
    using Matrix2 = Eigen::Matrix<Scalar, 2, 2>;
    const Matrix2 jac = jacobian.cast<Scalar>();
    const Scalar det = std::abs(jac.determinant());
    // ∇_x = J^{-T} ∇_ξ and H_x = J^{-T} H_ξ J^{-1}; G = J^{-1} J^{-T} collects the metric.
    const Matrix2 jinv = jac.inverse();
    const Matrix2 g = jinv * jinv.transpose();
    switch (form) {
      case BilinearForm::mass:
        add(kValue, kValue, det);
        break;
      case BilinearForm::laplace:
        for (int a = 0; a < 2; ++a)
          for (int b = 0; b < 2; ++b) add(kDxi + a, kDxi + b, det * g(a, b));
        break;
      case BilinearForm::bilaplace: {
        // Δ_x φ = Σ_ab G_ab ∂_ab φ = G_00 ∂ξξ + 2 G_01 ∂ξη + G_11 ∂ηη.
        const Scalar alpha[3] = {g(0, 0), 2 * g(0, 1), g(1, 1)};
        for (int p = 0; p < 3; ++p)
          for (int q = 0; q < 3; ++q) add(kDxixi + p, kDxixi + q, det * alpha[p] * alpha[q]);
        break;
      }
      case BilinearForm::hessian:
        // H_x(φ) : H_x(ψ) = Σ_abcd G_ac G_bd ∂_ab φ ∂_cd ψ.
        for (int a = 0; a < 2; ++a)
          for (int b = 0; b < 2; ++b)
            for (int c = 0; c < 2; ++c)
              for (int d = 0; d < 2; ++d) add(kDxixi + a + b, kDxixi + c + d, det * g(a, c) * g(b, d));
        break;
    }
  }
  return out;
}

template AffineTerms<double> affine_form_terms<double>(BilinearForm, const Eigen::Matrix2d&);
template AffineTerms<long double> affine_form_terms<long double>(BilinearForm, const Eigen::Matrix2d&);
template AffineTerms<DoubleDouble> affine_form_terms<DoubleDouble>(BilinearForm, const Eigen::Matrix2d&);

template <class Scalar>
void combine(const AffineTerms<Scalar>& terms, const ReferenceIntegrals<Eigen::Matrix<Scalar, -1, -1>>& r,
             Eigen::Matrix<Scalar, -1, -1>& k) {
  const Eigen::Index n = r(terms.term[0].alpha, terms.term[0].beta).rows();
  k.setZero(n, n);
  for (const ReferenceTerm<Scalar>& t : terms) k += t.weight * r(t.alpha, t.beta);
}

template void combine<double>(const AffineTerms<double>&, const ReferenceIntegrals<Eigen::MatrixXd>&, Eigen::MatrixXd&);
template void combine<long double>(const AffineTerms<long double>&, const ReferenceIntegrals<LongDoubleMatrix>&,
                                   LongDoubleMatrix&);

void combine(const AffineTerms<DoubleDouble>& terms, const ReferenceIntegrals<DoubleDoubleMatrix>& r,
             DoubleDoubleMatrix& k) {
  const DoubleDoubleMatrix* table[16];
  for (int t = 0; t < terms.size; ++t) table[t] = &r(terms.term[t].alpha, terms.term[t].beta);
  const Eigen::Index n = table[0]->rows();
  k.resize(n, n);
  for (Eigen::Index j = 0; j < n; ++j)
    for (Eigen::Index i = 0; i <= j; ++i) {
      DoubleDouble s(0.0);
      for (int t = 0; t < terms.size; ++t) s += terms.term[t].weight * (*table[t])(i, j);
      k.set(i, j, s);
      k.set(j, i, s);
    }
}

void tensor_form_matrix(const DerivativeMoments<LongDoubleMatrix>& x, const DerivativeMoments<LongDoubleMatrix>& y,
                        const AffineTerms<long double>& terms, LongDoubleMatrix& k) {
  const int nx = static_cast<int>(x.moment[0][0].rows()), ny = static_cast<int>(y.moment[0][0].rows());
  k.setZero(nx * ny, nx * ny);
  for (const ReferenceTerm<long double>& t : terms) {
    const LongDoubleMatrix& X = x.moment[kOrderXi[t.alpha]][kOrderXi[t.beta]];
    const LongDoubleMatrix& Y = y.moment[kOrderEta[t.alpha]][kOrderEta[t.beta]];
    for (int j2 = 0; j2 < ny; ++j2)
      for (int i2 = 0; i2 < nx; ++i2)
        for (int j = 0; j < ny; ++j) {
          const long double yv = t.weight * Y(j, j2);
          for (int i = 0; i < nx; ++i) k(i + nx * j, i2 + nx * j2) += X(i, i2) * yv;
        }
  }
}

namespace {

/// k(a + b nx, c + d nx) = Σ_t weighted_t(a, c) y_t(b, d) on the upper triangle, mirrored
/// (compiled twice, see exact_product in double_double.hpp).
template <bool kFma>
[[gnu::always_inline]] inline void tensor_entries(const std::vector<DoubleDoubleMatrix>& weighted,
                                                  const std::vector<const DoubleDoubleMatrix*>& y,
                                                  DoubleDoubleMatrix& k) {
  const int nx = static_cast<int>(weighted.front().rows()), ny = static_cast<int>(y.front()->rows());
  for (int d = 0; d < ny; ++d)
    for (int c = 0; c < nx; ++c) {
      const int j = c + d * nx;
      for (int b = 0; b < ny; ++b)
        for (int a = 0; a < nx; ++a) {
          const int i = a + b * nx;
          if (i > j) continue;
          DoubleDouble s(0.0);
          for (std::size_t t = 0; t < weighted.size(); ++t) s += multiply<kFma>(weighted[t](a, c), (*y[t])(b, d));
          k.set(i, j, s);
          k.set(j, i, s);
        }
    }
}

[[gnu::target("avx2,fma")]] void tensor_entries_fma(const std::vector<DoubleDoubleMatrix>& weighted,
                                                     const std::vector<const DoubleDoubleMatrix*>& y,
                                                     DoubleDoubleMatrix& k) {
  tensor_entries<true>(weighted, y, k);
}

}  // namespace

void tensor_form_matrix(const DerivativeMoments<DoubleDoubleMatrix>& x, const DerivativeMoments<DoubleDoubleMatrix>& y,
                        const AffineTerms<DoubleDouble>& terms, DoubleDoubleMatrix& k) {
  DoubleDouble largest(0.0);
  for (const ReferenceTerm<DoubleDouble>& t : terms) largest = std::max(largest, abs(t.weight));
  const int nx = static_cast<int>(x.moment[0][0].rows()), ny = static_cast<int>(y.moment[0][0].rows());
  // The weight goes into the x moments once per term (nx² products), so that an entry costs one
  // product per term.
  thread_local std::vector<DoubleDoubleMatrix> weighted;
  thread_local std::vector<const DoubleDoubleMatrix*> y_moment;
  weighted.clear();
  y_moment.clear();
  for (const ReferenceTerm<DoubleDouble>& t : terms) {
    if (abs(t.weight).hi <= 1e-20 * largest.hi) continue;
    const DoubleDoubleMatrix& m = x.moment[kOrderXi[t.alpha]][kOrderXi[t.beta]];
    DoubleDoubleMatrix& w = weighted.emplace_back();
    w.resize(nx, nx);
    for (int c = 0; c < nx; ++c)
      for (int a = 0; a < nx; ++a) w.set(a, c, t.weight * m(a, c));
    y_moment.push_back(&y.moment[kOrderEta[t.alpha]][kOrderEta[t.beta]]);
  }
  k.resize(nx * ny, nx * ny);
  if (cpu_has_avx2_fma())
    tensor_entries_fma(weighted, y_moment, k);
  else
    tensor_entries<false>(weighted, y_moment, k);
}

namespace {

/// The nonzeros of C by column: column m holds nz[start[m] .. start[m + 1]) as (row, value).
struct ColumnNonzeros {
  std::vector<std::pair<int, double>> nz;
  std::vector<int> start;
  void build(const Eigen::MatrixXd& c) {
    nz.clear();
    start.assign(c.cols() + 1, 0);
    for (Eigen::Index m = 0; m < c.cols(); ++m) {
      start[m] = static_cast<int>(nz.size());
      for (Eigen::Index i = 0; i < c.rows(); ++i)
        if (c(i, m) != 0) nz.emplace_back(static_cast<int>(i), c(i, m));
    }
    start[c.cols()] = static_cast<int>(nz.size());
  }
};

/// One term of a compensated dot product (Ogita–Rump–Oishi Dot2): s + e += a b with the product
/// exact and the rounding of the sum kept in e.
inline void dot2_step(double& s, double& e, double a, double b) {
  const DoubleDouble p = dd_detail::two_prod(a, b);
  const DoubleDouble t = dd_detail::two_sum(s, p.hi);
  s = t.hi;
  e += t.lo + p.lo;
}

}  // namespace

template <class MatrixK>
void symmetric_congruence(const Eigen::MatrixXd& c, const MatrixK& k, LongDoubleMatrix& out) {
  const int nl = static_cast<int>(c.rows()), na = static_cast<int>(c.cols());
  thread_local ColumnNonzeros columns;
  thread_local std::vector<long double> ctk;
  columns.build(c);
  const auto& nz = columns.nz;
  const auto& start = columns.start;
  // (Cᵀ K)(m, j) = Σ_i C(i, m) K(i, j), kept in long double, row m contiguous; then the upper
  // triangle of (Cᵀ K) C, mirrored.
  ctk.resize(static_cast<std::size_t>(na) * nl);
  for (int m = 0; m < na; ++m)
    for (int j = 0; j < nl; ++j) {
      const auto* kj = k.col(j).data();
      long double s = 0;
      for (int e = start[m]; e < start[m + 1]; ++e) s += static_cast<long double>(nz[e].second) * kj[nz[e].first];
      ctk[static_cast<std::size_t>(m) * nl + j] = s;
    }
  out.resize(na, na);
  for (int m = 0; m < na; ++m) {
    const long double* row = &ctk[static_cast<std::size_t>(m) * nl];
    for (int p = m; p < na; ++p) {
      long double s = 0;
      for (int e = start[p]; e < start[p + 1]; ++e) s += static_cast<long double>(nz[e].second) * row[nz[e].first];
      out(m, p) = out(p, m) = s;
    }
  }
}

template void symmetric_congruence<Eigen::MatrixXd>(const Eigen::MatrixXd&, const Eigen::MatrixXd&, LongDoubleMatrix&);
template void symmetric_congruence<LongDoubleMatrix>(const Eigen::MatrixXd&, const LongDoubleMatrix&, LongDoubleMatrix&);

void symmetric_congruence(const Eigen::MatrixXd& c, const DoubleDoubleMatrix& k, DoubleDoubleMatrix& local) {
  const int nl = static_cast<int>(c.rows()), na = static_cast<int>(c.cols());
  thread_local ColumnNonzeros columns;
  columns.build(c);
  const auto& nz = columns.nz;
  const auto& start = columns.start;
  // T = Cᵀ K (column-major: column i holds T(·, i), which the second product runs over). The
  // innermost loops run over independent sums, so the operations pipeline.
  thread_local Eigen::MatrixXd tt_hi, tt_lo;
  thread_local std::vector<double> s, e;
  tt_hi.resize(na, nl);
  tt_lo.resize(na, nl);
  s.resize(std::max(na, nl));
  e.resize(std::max(na, nl));
  for (int m = 0; m < na; ++m) {
    std::fill_n(s.begin(), nl, 0.0);
    std::fill_n(e.begin(), nl, 0.0);
    for (int p = start[m]; p < start[m + 1]; ++p) {
      const auto [i, v] = nz[p];
      const double* khi = k.hi.col(i).data();  // K symmetric: column i is row i
      const double* klo = k.lo.col(i).data();
      for (int j = 0; j < nl; ++j) {
        dot2_step(s[j], e[j], v, khi[j]);
        e[j] += v * klo[j];
      }
    }
    for (int j = 0; j < nl; ++j) {
      const DoubleDouble t = dd_detail::quick_two_sum(s[j], e[j]);
      tt_hi(m, j) = t.hi;
      tt_lo(m, j) = t.lo;
    }
  }
  // (Cᵀ K C)(m, q) = Σ_i T(m, i) C(i, q) for m <= q, mirrored.
  local.resize(na, na);
  for (int q = 0; q < na; ++q) {
    std::fill_n(s.begin(), q + 1, 0.0);
    std::fill_n(e.begin(), q + 1, 0.0);
    for (int p = start[q]; p < start[q + 1]; ++p) {
      const auto [i, v] = nz[p];
      const double* thi = tt_hi.col(i).data();
      const double* tlo = tt_lo.col(i).data();
      for (int m = 0; m <= q; ++m) {
        dot2_step(s[m], e[m], v, thi[m]);
        e[m] += v * tlo[m];
      }
    }
    for (int m = 0; m <= q; ++m) {
      const DoubleDouble t = dd_detail::quick_two_sum(s[m], e[m]);
      local.set(m, q, t);
      local.set(q, m, t);
    }
  }
}

void affine_element_matrix(BilinearForm form, const Eigen::Matrix2d& jacobian, const ReferenceIntegrals<Eigen::MatrixXd>& r,
                           const Eigen::MatrixXd& c, Eigen::MatrixXd& out) {
  thread_local Eigen::MatrixXd k;
  thread_local LongDoubleMatrix extended;
  combine(affine_form_terms<double>(form, jacobian), r, k);
  symmetric_congruence(c, k, extended);
  out = extended.cast<double>();
}

void affine_element_matrix(BilinearForm form, const Eigen::Matrix2d& jacobian, const ReferenceIntegrals<LongDoubleMatrix>& r,
                           const Eigen::MatrixXd& c, LongDoubleMatrix& out) {
  thread_local LongDoubleMatrix k;
  combine(affine_form_terms<long double>(form, jacobian), r, k);
  symmetric_congruence(c, k, out);
}

void affine_element_matrix(BilinearForm form, const Eigen::Matrix2d& jacobian,
                           const ReferenceIntegrals<DoubleDoubleMatrix>& r, const Eigen::MatrixXd& c,
                           DoubleDoubleMatrix& out) {
  thread_local DoubleDoubleMatrix k;
  combine(affine_form_terms<DoubleDouble>(form, jacobian), r, k);
  symmetric_congruence(c, k, out);
}

}  // namespace iga
