#include "spaces/tmesh/tmesh_closed_forms.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <functional>
#include <span>
#include <string_view>
#include <tuple>

#include "quadrature/quadrature_rule.hpp"

namespace iga {

TMeshClosedForms::TMeshClosedForms(const TMeshSpace& space) : space_(space) {
  // Side integrals with the 1D Gauss rule of the assembly's tensor rule on coarse cells, and with
  // that rule's 8 extra points on fine ones too: the closed-form matrices go to the double-double
  // solve, where a quadrature error of 1e-17 is not round-off (the plate's L2 error moved by
  // 2e-4 relative with 4 extra points at w h = pi/128). They are computed once per side length.
  const int n = space.section().n;
  const QuadratureRule gauss = gauss_legendre_for_degree(2 * n + 1 + (space.extra_degree() > 0 ? kFullExtraDegree : 0));
  for (const auto& [key, b] : space.bernstein_bases()) {
    SideIntegrals& s = side_integrals_[key];
    for (auto& m : s.m) m.setZero(b.n() + 1, b.n() + 1);
    for (int k = 0; k < gauss.size(); ++k) {
      const Eigen::MatrixXd d = b.derivatives(gauss.points[k].x(), 2);
      const long double w = gauss.weights[k];
      for (int a = 0; a < 3; ++a)
        for (int c = 0; c < 3; ++c)
          for (int j = 0; j <= b.n(); ++j)
            for (int i = 0; i <= b.n(); ++i)
              s.m[3 * a + c](i, j) += w * static_cast<long double>(d(a, i)) * static_cast<long double>(d(c, j));
    }
    // Double-double: w d_i exact (two-product), then times d_j, summed with compensated additions.
    SideIntegralsDD& sd = side_integrals_dd_[key];
    sd.size = b.n() + 1;
    for (auto& m : sd.m) m.assign(sd.size * sd.size, DoubleDouble(0.0));
    for (int k = 0; k < gauss.size(); ++k) {
      const Eigen::MatrixXd d = b.derivatives(gauss.points[k].x(), 2);
      const double w = gauss.weights[k];
      for (int a = 0; a < 3; ++a)
        for (int c = 0; c < 3; ++c)
          for (int j = 0; j < sd.size; ++j)
            for (int i = 0; i < sd.size; ++i)
              sd.m[3 * a + c][i + sd.size * j] += dd_detail::two_prod(w, d(a, i)) * d(c, j);
    }
  }
  static std::atomic<std::uint64_t> next_instance{1};
  instance_id_ = next_instance++;
}

namespace {

/// Terms c ∫ ∂x^a ∂y^b u ∂x^a' ∂y^b' v of each form = c hx hy hx^-(a+a') hy^-(b+b') X(a, a') ⊗ Y(b, b').
struct FormTerm {
  int a, b, a2, b2, c;
};
std::span<const FormTerm> form_terms(BilinearForm form) {
  static constexpr FormTerm mass[] = {{0, 0, 0, 0, 1}}, laplace[] = {{1, 0, 1, 0, 1}, {0, 1, 0, 1, 1}},
                            bilaplace[] = {{2, 0, 2, 0, 1}, {2, 0, 0, 2, 1}, {0, 2, 2, 0, 1}, {0, 2, 0, 2, 1}},
                            hessian[] = {{2, 0, 2, 0, 1}, {1, 1, 1, 1, 2}, {0, 2, 0, 2, 1}};
  switch (form) {
    case BilinearForm::mass: return mass;
    case BilinearForm::laplace: return laplace;
    case BilinearForm::bilaplace: return bilaplace;
    case BilinearForm::hessian: return hessian;
  }
  return {};
}

/// x^p in double-double (p small).
DoubleDouble power(double x, int p) {
  DoubleDouble r(1.0);
  for (int k = 0; k < p; ++k) r = r * x;
  return r;
}

}  // namespace

bool TMeshClosedForms::double_double(int element, BilinearForm form, DoubleDoubleMatrix& local) const {
  const TMesh& mesh_ = space_.mesh();
  const TCell& cell = mesh_.cells()[element];
  // K_c depends on the form, the sections and the side lengths only: a dyadic mesh has a handful,
  // so each thread keeps them (keyed by this space, whose id no later space reuses).
  using Key = std::tuple<int, int, std::int64_t, int, std::int64_t>;
  struct CellMatrix {
    int size = 0;
    std::vector<double> hi, lo;  // column-major, size x size
  };
  struct Cache {
    std::uint64_t owner = 0;
    std::map<Key, CellMatrix> matrices;
  };
  thread_local Cache cache;
  if (cache.owner != instance_id_) {
    cache.owner = instance_id_;
    cache.matrices.clear();
  }
  const Key key{static_cast<int>(form), cell.section_s, cell.x1 - cell.x0, cell.section_t, cell.y1 - cell.y0};
  auto it = cache.matrices.find(key);
  if (it == cache.matrices.end()) {
    const SideIntegralsDD& sx = side_integrals_dd_.at(TMeshSpace::side_x(cell));
    const SideIntegralsDD& sy = side_integrals_dd_.at(TMeshSpace::side_y(cell));
    const double hx = mesh_.width(element), hy = mesh_.height(element);
    const int nx = sx.size, ny = sy.size, nl = nx * ny;
    std::vector<DoubleDouble> k(static_cast<std::size_t>(nl) * nl, DoubleDouble(0.0));
    for (const FormTerm& t : form_terms(form)) {
      const DoubleDouble scale =
          dd_detail::two_prod(hx, hy) * static_cast<double>(t.c) / (power(hx, t.a + t.a2) * power(hy, t.b + t.b2));
      const std::vector<DoubleDouble>& X = sx.m[3 * t.a + t.a2];
      const std::vector<DoubleDouble>& Y = sy.m[3 * t.b + t.b2];
      for (int j2 = 0; j2 < ny; ++j2)
        for (int i2 = 0; i2 < nx; ++i2)
          for (int j = 0; j < ny; ++j) {
            const DoubleDouble yv = scale * Y[j + ny * j2];
            for (int i = 0; i < nx; ++i) k[(i + nx * j) + nl * (i2 + nx * j2)] += X[i + nx * i2] * yv;
          }
    }
    CellMatrix m;
    m.size = nl;
    m.hi.resize(k.size());
    m.lo.resize(k.size());
    for (std::size_t q = 0; q < k.size(); ++q) m.hi[q] = k[q].hi, m.lo[q] = k[q].lo;
    it = cache.matrices.emplace(key, std::move(m)).first;
  }
  const CellMatrix& k = it->second;
  const Eigen::MatrixXd& e = space_.extraction().matrix[element];
  // Cells of one size away from T-junctions and the boundary share E_c as well (the same Hermite
  // functions, the same scaling): their matrices are computed once, looked up by the bytes of E_c.
  struct Known {
    Eigen::MatrixXd e;
    DoubleDoubleMatrix local;
  };
  thread_local std::map<std::pair<const CellMatrix*, std::size_t>, std::vector<Known>> known;
  thread_local std::uint64_t known_owner = 0;
  thread_local std::size_t known_count = 0;
  if (known_owner != instance_id_ || known_count > 1024) {  // bounded (a few MB): graded meshes have many
    known_owner = instance_id_;
    known.clear();
    known_count = 0;
  }
  const std::size_t hash = std::hash<std::string_view>{}(
      std::string_view(reinterpret_cast<const char*>(e.data()), static_cast<std::size_t>(e.size()) * sizeof(double)));
  std::vector<Known>& same_hash = known[{&k, hash}];
  for (const Known& c : same_hash)
    if (c.e.rows() == e.rows() && c.e.cols() == e.cols() && c.e == e) {
      local = c.local;
      return true;
    }
  const int na = static_cast<int>(e.rows()), nl = k.size;
  // The nonzeros of each row of E_c (a vertex or edge function touches a corner or side block of
  // the cell's Bernstein coefficients only).
  thread_local std::vector<int> start, column;
  thread_local std::vector<double> value;
  start.assign(1, 0);
  column.clear();
  value.clear();
  for (int a = 0; a < na; ++a) {
    for (int p = 0; p < nl; ++p)
      if (e(a, p) != 0.0) column.push_back(p), value.push_back(e(a, p));
    start.push_back(static_cast<int>(column.size()));
  }
  // EK = E_c K_c, then local(a, b) = Σ_q EK(a, q) E_c(b, q) for a <= b. The innermost loops run
  // over independent sums (q, then a), so the double-double operations pipeline instead of waiting
  // on one chain of dependent additions.
  thread_local std::vector<double> ek_hi, ek_lo, acc_hi, acc_lo;  // EK column-major (na x nl)
  ek_hi.assign(static_cast<std::size_t>(na) * nl, 0.0);
  ek_lo.assign(static_cast<std::size_t>(na) * nl, 0.0);
  for (int a = 0; a < na; ++a)
    for (int s = start[a]; s < start[a + 1]; ++s) {
      const double v = value[s];
      const double* k_hi = k.hi.data() + static_cast<std::size_t>(nl) * column[s];  // K(., p) = K(p, .)
      const double* k_lo = k.lo.data() + static_cast<std::size_t>(nl) * column[s];
      for (int q = 0; q < nl; ++q) {
        const std::size_t at = static_cast<std::size_t>(q) * na + a;
        const DoubleDouble sum = DoubleDouble(ek_hi[at], ek_lo[at]) + DoubleDouble(k_hi[q], k_lo[q]) * v;
        ek_hi[at] = sum.hi, ek_lo[at] = sum.lo;
      }
    }
  local.resize(na, na);
  acc_hi.resize(na);
  acc_lo.resize(na);
  for (int b = 0; b < na; ++b) {
    std::fill_n(acc_hi.begin(), b + 1, 0.0);
    std::fill_n(acc_lo.begin(), b + 1, 0.0);
    for (int s = start[b]; s < start[b + 1]; ++s) {
      const double v = value[s];
      const double* e_hi = ek_hi.data() + static_cast<std::size_t>(na) * column[s];
      const double* e_lo = ek_lo.data() + static_cast<std::size_t>(na) * column[s];
      for (int a = 0; a <= b; ++a) {
        const DoubleDouble sum = DoubleDouble(acc_hi[a], acc_lo[a]) + DoubleDouble(e_hi[a], e_lo[a]) * v;
        acc_hi[a] = sum.hi, acc_lo[a] = sum.lo;
      }
    }
    for (int a = 0; a <= b; ++a) {
      local.hi(a, b) = local.hi(b, a) = acc_hi[a];
      local.lo(a, b) = local.lo(b, a) = acc_lo[a];
    }
  }
  same_hash.push_back({e, local});
  ++known_count;
  return true;
}

bool TMeshClosedForms::extended(int element, BilinearForm form, LongDoubleMatrix& local) const {
  const TMesh& mesh_ = space_.mesh();
  using MatrixL = Eigen::Matrix<long double, Eigen::Dynamic, Eigen::Dynamic>;
  const TCell& cell = mesh_.cells()[element];
  const SideIntegrals& sx = side_integrals_.at(TMeshSpace::side_x(cell));
  const SideIntegrals& sy = side_integrals_.at(TMeshSpace::side_y(cell));
  const long double hx = mesh_.width(element), hy = mesh_.height(element);
  // Terms c ∫ ∂x^a ∂y^b u ∂x^a' ∂y^b' v = c hx hy hx^-(a+a') hy^-(b+b') X(a, a') ⊗ Y(b, b').
  struct Term {
    int a, b, a2, b2;
    long double c;
  };
  static constexpr Term mass[] = {{0, 0, 0, 0, 1}}, laplace[] = {{1, 0, 1, 0, 1}, {0, 1, 0, 1, 1}},
                        bilaplace[] = {{2, 0, 2, 0, 1}, {2, 0, 0, 2, 1}, {0, 2, 2, 0, 1}, {0, 2, 0, 2, 1}},
                        hessian[] = {{2, 0, 2, 0, 1}, {1, 1, 1, 1, 2}, {0, 2, 0, 2, 1}};
  std::span<const Term> terms;
  switch (form) {
    case BilinearForm::mass: terms = mass; break;
    case BilinearForm::laplace: terms = laplace; break;
    case BilinearForm::bilaplace: terms = bilaplace; break;
    case BilinearForm::hessian: terms = hessian; break;
  }
  const int nx = static_cast<int>(sx.m[0].rows()), ny = static_cast<int>(sy.m[0].rows());
  thread_local MatrixL k, e, ek;  // scratch: no allocation per element
  k.setZero(nx * ny, nx * ny);    // local index i + nx j (x fastest, as the evaluator)
  for (const Term& t : terms) {
    const long double scale = t.c * hx * hy / (std::pow(hx, t.a + t.a2) * std::pow(hy, t.b + t.b2));
    const MatrixL& X = sx.m[3 * t.a + t.a2];
    const MatrixL& Y = sy.m[3 * t.b + t.b2];
    for (int j2 = 0; j2 < ny; ++j2)
      for (int i2 = 0; i2 < nx; ++i2)
        for (int j = 0; j < ny; ++j) {
          const long double yv = scale * Y(j, j2);
          for (int i = 0; i < nx; ++i) k(i + nx * j, i2 + nx * j2) += X(i, i2) * yv;
        }
  }
  e = space_.extraction().matrix[element].cast<long double>();
  // Small products: coefficient-based, no GEMM packing (which dominated at these sizes); the
  // result is symmetric, so the second product fills the upper triangle and mirrors it.
  ek = e.lazyProduct(k);
  const Eigen::Index na = e.rows();
  local.resize(na, na);
  for (Eigen::Index j = 0; j < na; ++j)
    for (Eigen::Index i = 0; i <= j; ++i) local(i, j) = local(j, i) = ek.row(i).dot(e.row(j));
  return true;
}

bool TMeshClosedForms::rounded(int element, BilinearForm form, Eigen::MatrixXd& local) const {
  LongDoubleMatrix extended;
  this->extended(element, form, extended);
  local = extended.cast<double>();
  return true;
}

}  // namespace iga
