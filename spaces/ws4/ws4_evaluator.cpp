#include "spaces/ws4/ws4_evaluator.hpp"

#include <Eigen/LU>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "config/cpu_dispatch.hpp"
#include "spaces/ws4/ws4_basis.hpp"
#include "spaces/ws4/ws4_space.hpp"

namespace iga::ws4 {

namespace {

constexpr int kMonomials = Poly4::size;

/// Per region of the split, the reference functions whose piece there is not zero and their
/// monomial coefficients as columns (15 x active): most simplex splines vanish on most regions.
struct RegionPieces {
  std::vector<int> active;
  Eigen::Matrix<double, kMonomials, Eigen::Dynamic> coefficients;
};

const std::vector<RegionPieces>& region_pieces() {
  static const std::vector<RegionPieces> pieces = [] {
    const Ws4Basis& basis = Ws4Basis::reference();
    const int nr = static_cast<int>(basis.split().regions().size());
    std::vector<RegionPieces> out(nr);
    for (int r = 0; r < nr; ++r) {
      for (int i = 0; i < Ws4Basis::size; ++i)
        if (!basis.piece(r, i).is_zero()) out[r].active.push_back(i);
      out[r].coefficients.resize(kMonomials, static_cast<Eigen::Index>(out[r].active.size()));
      for (size_t m = 0; m < out[r].active.size(); ++m)
        for (int a = 0; a <= Poly4::max_degree; ++a)
          for (int b = 0; a + b <= Poly4::max_degree; ++b)
            out[r].coefficients(Poly4::index(a, b), static_cast<Eigen::Index>(m)) =
                basis.piece(r, out[r].active[m]).coefficient(a, b);
    }
    return out;
  }();
  return pieces;
}

/// Rows value, dx, dy, dxx, dxy, dyy of the physical derivatives of the reference polynomial p
/// (15 monomial coefficients) under ξ = G (x - p0): ∂x_j = Σ_k G(k, j) ∂ξ_k.
void physical_derivatives(const double* p, const Eigen::Matrix2d& g, int rows, Eigen::Matrix<double, 6, 15>& d) {
  d.topRows(rows).setZero();
  double pxi[kMonomials] = {}, peta[kMonomials] = {}, pxx[kMonomials] = {}, pxe[kMonomials] = {},
         pee[kMonomials] = {};
  for (int a = 0; a <= Poly4::max_degree; ++a)
    for (int b = 0; a + b <= Poly4::max_degree; ++b) {
      const double v = p[Poly4::index(a, b)];
      d(0, Poly4::index(a, b)) = v;
      if (rows == 1) continue;
      if (a > 0) pxi[Poly4::index(a - 1, b)] = a * v;
      if (b > 0) peta[Poly4::index(a, b - 1)] = b * v;
      if (a > 1) pxx[Poly4::index(a - 2, b)] = a * (a - 1) * v;
      if (a > 0 && b > 0) pxe[Poly4::index(a - 1, b - 1)] = a * b * v;
      if (b > 1) pee[Poly4::index(a, b - 2)] = b * (b - 1) * v;
    }
  if (rows == 1) return;
  for (int k = 0; k < 10; ++k) {  // first derivatives have degree <= 3: the first 10 monomials
    d(1, k) = g(0, 0) * pxi[k] + g(1, 0) * peta[k];
    d(2, k) = g(0, 1) * pxi[k] + g(1, 1) * peta[k];
  }
  if (rows == 3) return;
  for (int k = 0; k < 6; ++k) {  // second derivatives: degree <= 2
    d(3, k) = g(0, 0) * g(0, 0) * pxx[k] + 2 * g(0, 0) * g(1, 0) * pxe[k] + g(1, 0) * g(1, 0) * pee[k];
    d(4, k) = g(0, 0) * g(0, 1) * pxx[k] + (g(0, 0) * g(1, 1) + g(1, 0) * g(0, 1)) * pxe[k] + g(1, 0) * g(1, 1) * pee[k];
    d(5, k) = g(0, 1) * g(0, 1) * pxx[k] + 2 * g(0, 1) * g(1, 1) * pxe[k] + g(1, 1) * g(1, 1) * pee[k];
  }
}

/// moments(m) += Σ_k weights(first + k) monomials(first + k, m) for the 15 monomials: dot products
/// of contiguous arrays (AVX2 clone as below).
IGA_AVX2_CLONES
void add_moments(const double* monomials, Eigen::Index stride, const double* weights, int first, int count,
                 double* moments) {
  const double* w = weights + first;
  for (int m = 0; m < kMonomials; ++m) {
    const double* mm = monomials + m * stride + first;
    double sum[4] = {0, 0, 0, 0};  // four independent sums: one vector of lanes
    int k = 0;
    for (; k + 4 <= count; k += 4)
      for (int lane = 0; lane < 4; ++lane) sum[lane] += mm[k + lane] * w[k + lane];
    for (; k < count; ++k) sum[0] += mm[k] * w[k];
    moments[m] += (sum[0] + sum[1]) + (sum[2] + sum[3]);
  }
}

/// p(x, y) for a polynomial of degree <= D with coefficients in Poly4 index order: Horner in x for
/// each power of y, then Horner in y (14 multiply-adds for a quartic).
template <int D>
inline double horner(const double* c, double x, double y) {
  double outer = 0;
  for (int b = D; b >= 0; --b) {
    double inner = c[Poly4::index(D - b, b)];
    for (int a = D - b - 1; a >= 0; --a) inner = inner * x + c[Poly4::index(a, b)];
    outer = outer * y + inner;
  }
  return outer;
}

/// Rows value, dx, dy, dxx, dxy, dyy (the first `rows`) of u_h at the `count` points of a run from
/// its per-region polynomials `d` (value quartic, first derivatives cubic, second ones quadratic)
/// and the points' coordinates relative to the region's center: Horner per point, which reads two
/// numbers per point instead of a table of 15 monomials. Compiled twice, the AVX2 body chosen at
/// load time where the CPU has it (four points per instruction instead of two).
IGA_AVX2_CLONES
void run_values(const Eigen::Matrix<double, 6, 15>& d, int rows, const double* __restrict x,
                const double* __restrict y, int count, double* const* out) {
  double c[6][15];
  for (int r = 0; r < rows; ++r)
    for (int m = 0; m < 15; ++m) c[r][m] = d(r, m);
  double* __restrict value = out[0];
  for (int k = 0; k < count; ++k) value[k] = horner<4>(c[0], x[k], y[k]);
  if (rows < 3) return;
  double* __restrict dx = out[1];
  double* __restrict dy = out[2];
  for (int k = 0; k < count; ++k) {
    dx[k] = horner<3>(c[1], x[k], y[k]);
    dy[k] = horner<3>(c[2], x[k], y[k]);
  }
  if (rows < 6) return;
  double* __restrict dxx = out[3];
  double* __restrict dxy = out[4];
  double* __restrict dyy = out[5];
  for (int k = 0; k < count; ++k) {
    dxx[k] = horner<2>(c[3], x[k], y[k]);
    dxy[k] = horner<2>(c[4], x[k], y[k]);
    dyy[k] = horner<2>(c[5], x[k], y[k]);
  }
}

}  // namespace

const Ws4PieceEvaluation::RuleTables& Ws4PieceEvaluation::tables(const QuadratureRule& rule) {
  auto it = cache_.find(&rule);
  // Bitwise comparison (memcmp, not point by point): it runs once per element and rule.
  if (it != cache_.end() && it->second.points.size() == rule.points.size() &&
      std::memcmp(it->second.points.data(), rule.points.data(), rule.points.size() * sizeof(Point2)) == 0)
    return it->second;
  if (it == cache_.end() && cache_.size() >= 64) cache_.clear();  // bound temporary rules
  RuleTables& t = cache_[&rule];
  const Ws4Basis& basis = Ws4Basis::reference();
  const int q = rule.size();
  t.points = rule.points;
  t.reference.resize(2, q);
  t.monomials.resize(q, kMonomials);
  t.local.resize(q, 2);
  t.regions.clear();
  t.runs.clear();
  std::vector<int> slot(basis.split().regions().size(), -1);
  for (int k = 0; k < q; ++k) {
    t.reference.col(k) = rule.points[k];
    const int r = basis.split().locate(rule.points[k]);
    if (slot[r] < 0) {
      slot[r] = static_cast<int>(t.regions.size());
      t.regions.push_back(r);
    }
    if (!t.runs.empty() && t.runs.back()[0] == slot[r])
      ++t.runs.back()[2];
    else
      t.runs.push_back({slot[r], k, 1});
    const Point2 x = rule.points[k] - basis.center(r);
    t.local(k, 0) = x.x();
    t.local(k, 1) = x.y();
    for (int a = 0; a <= Poly4::max_degree; ++a)
      for (int b = 0; a + b <= Poly4::max_degree; ++b)
        t.monomials(k, Poly4::index(a, b)) = std::pow(x.x(), a) * std::pow(x.y(), b);
  }
  return t;
}

void Ws4PieceEvaluation::fill_geometry(int element, const RuleTables& t, PointValues& out) const {
  space_.element_dofs(element, out.dofs);
  const Eigen::Matrix2d j = space_.jacobian(element);
  const Point2 p0 = space_.mesh().vertices()[space_.mesh().triangle(element)[0]];
  out.x.noalias() = j * t.reference;
  out.x.colwise() += p0;
  out.jacobian.assign(t.points.size(), j);
}

void Ws4PieceEvaluation::evaluate_geometry(int element, const QuadratureRule& rule, PointValues& out) {
  fill_geometry(element, tables(rule), out);
}

void Ws4PieceEvaluation::evaluate_function(int element, const QuadratureRule& rule, const Eigen::VectorXd& coefficients,
                                           unsigned flags, PointValues& geometry, FunctionValues& out) {
  if (flags & (update_laplacian_gradient | update_bilaplacian))
    throw std::logic_error("evaluate_function: this space provides derivatives up to order 2 only");
  const RuleTables& t = tables(rule);
  fill_geometry(element, t, geometry);
  for (int i = 0; i < Ws4Basis::size; ++i) c_(i) = coefficients(geometry.dofs[i]);
  b_.noalias() = space_.extraction(element) * c_;

  // u_h on each region holding points: 15 monomial coefficients in that region's coordinates.
  const auto& pieces = region_pieces();
  region_coefficients_.resize(kMonomials, static_cast<Eigen::Index>(t.regions.size()));
  for (size_t s = 0; s < t.regions.size(); ++s) {
    const RegionPieces& rp = pieces[t.regions[s]];
    auto column = region_coefficients_.col(static_cast<Eigen::Index>(s));
    column.setZero();
    for (size_t m = 0; m < rp.active.size(); ++m)
      column += b_(rp.active[m]) * rp.coefficients.col(static_cast<Eigen::Index>(m));
  }

  const bool hess = (flags & update_hessians) != 0;
  const bool grads = hess || (flags & update_gradients) != 0;
  const int rows = hess ? 6 : grads ? 3 : 1;
  const Eigen::Matrix2d g = space_.jacobian(element).inverse();
  const int q = rule.size();
  Eigen::VectorXd* targets[6] = {&out.value, &out.dx, &out.dy, &out.dxx, &out.dxy, &out.dyy};
  for (int r = 0; r < rows; ++r) targets[r]->resize(q);
  for (const auto& [s, first, count] : t.runs) {
    physical_derivatives(region_coefficients_.col(s).data(), g, rows, derivatives_);
    double* rows_out[6];
    for (int r = 0; r < rows; ++r) rows_out[r] = targets[r]->data() + first;
    run_values(derivatives_, rows, t.local.col(0).data() + first, t.local.col(1).data() + first, count, rows_out);
  }
}

void Ws4PieceEvaluation::integrate_values(int element, const QuadratureRule& rule, const Eigen::VectorXd& weights,
                                          Eigen::VectorXd& local) {
  const RuleTables& t = tables(rule);
  // Weighted monomial moments per region, then Σ_r (pieces of r)ᵀ moments.
  region_coefficients_.setZero(kMonomials, static_cast<Eigen::Index>(t.regions.size()));
  for (const auto& [s, first, count] : t.runs)
    add_moments(t.monomials.data(), t.monomials.outerStride(), weights.data(), first, count,
                region_coefficients_.col(s).data());
  const auto& pieces = region_pieces();
  b_.setZero();
  for (size_t s = 0; s < t.regions.size(); ++s) {
    const RegionPieces& rp = pieces[t.regions[s]];
    const auto moments = region_coefficients_.col(static_cast<Eigen::Index>(s));
    for (size_t m = 0; m < rp.active.size(); ++m)
      b_(rp.active[m]) += rp.coefficients.col(static_cast<Eigen::Index>(m)).dot(moments);
  }
  local.noalias() = space_.extraction(element).transpose() * b_;
}

}  // namespace iga::ws4
