#include "spaces/ws4/ws4_reference_matrices.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "spaces/ws4/ws4_basis.hpp"

namespace iga::ws4 {

namespace {

/// The indices i < n whose piece `piece(i)` is not zero (increasing) into `active`, and each such
/// piece with its derivatives ∂x, ∂y, ∂xx, ∂xy, ∂yy as entry k (its place in `active`) of the six
/// blocks of n in `d`. Returns their number.
template <class Poly, class PieceOf>
int active_pieces(PieceOf piece, int n, std::vector<int>& active, std::vector<Poly>& d) {
  active.clear();
  for (int i = 0; i < n; ++i) {
    const Poly& p = piece(i);
    if (p.is_zero()) continue;
    const int k = static_cast<int>(active.size());
    active.push_back(i);
    d[k] = p;
    d[n + k] = p.derivative(0);
    d[2 * n + k] = p.derivative(1);
    d[3 * n + k] = d[n + k].derivative(0);
    d[4 * n + k] = d[n + k].derivative(1);
    d[5 * n + k] = d[2 * n + k].derivative(1);
  }
  return static_cast<int>(active.size());
}

using Real = long double;
/// The pairs of derivative tables (value, ∂ξ, ∂η, ∂ξξ, ∂ξη, ∂ηη) integrated: ∫ table_k table_lᵀ.
const int kPairs[10][2] = {{0, 0}, {1, 1}, {1, 2}, {2, 2}, {3, 3}, {3, 4}, {3, 5}, {4, 4}, {4, 5}, {5, 5}};
using MatrixL = LongDoubleMatrix;

/// g-point Gauss–Legendre (g = 3, 4 or 5, exact to degree 2g - 1) on [0, 1] in T (long double or
/// double-double): nodes x, weights w.
template <class T>
void gauss_legendre_unit(int g, T* x, T* w) {
  using std::sqrt;
  T nodes[5], weights[5];
  if (g == 3) {
    const T a = sqrt(T(3.0) / T(5.0));
    nodes[0] = -a, nodes[1] = T(0.0), nodes[2] = a;
    weights[0] = weights[2] = T(5.0) / T(9.0);
    weights[1] = T(8.0) / T(9.0);
  } else if (g == 4) {
    const T r = sqrt(T(6.0) / T(5.0)) * 2.0 / T(7.0);
    const T a = sqrt(T(3.0) / T(7.0) - r), b = sqrt(T(3.0) / T(7.0) + r);
    const T s30 = sqrt(T(30.0));
    const T wa = (T(18.0) + s30) / T(36.0), wb = (T(18.0) - s30) / T(36.0);
    nodes[0] = -b, nodes[1] = -a, nodes[2] = a, nodes[3] = b;
    weights[0] = weights[3] = wb;
    weights[1] = weights[2] = wa;
  } else {
    const T r = sqrt(T(10.0) / T(7.0));
    const T a = sqrt(T(5.0) - r * 2.0) / T(3.0), b = sqrt(T(5.0) + r * 2.0) / T(3.0);
    const T s70 = sqrt(T(70.0));
    const T wa = (T(322.0) + s70 * 13.0) / T(900.0), wb = (T(322.0) - s70 * 13.0) / T(900.0);
    const T n5[5] = {-b, -a, T(0.0), a, b}, w5[5] = {wb, wa, T(128.0) / T(225.0), wa, wb};
    for (int k = 0; k < 5; ++k) nodes[k] = n5[k], weights[k] = w5[k];
  }
  for (int k = 0; k < g; ++k) {
    x[k] = (nodes[k] + T(1.0)) * 0.5;
    w[k] = weights[k] * 0.5;
  }
}

/// The collapsed g x g Gauss rule on fan triangle `f` of the split, in T (long double or
/// double-double): points relative to the centre of the fan's region (the pieces' origin), from
/// the corners' exact barycentrics, and weights. Collapsed coordinates:
/// x = v0 + s (v1 − v0) + (1 − s) t (v2 − v0), dx = (1 − s) 2|T| ds dt.
template <class T>
void fan_rule(const Ws4Basis& basis, int f, int g, const T* gx, const T* gw, T* x, T* y, T* w) {
  using std::abs;
  const Ws4Split& split = basis.split();
  const Point2 center = basis.center(split.fan_region()[f]);
  T vx[3], vy[3];
  for (int k = 0; k < 3; ++k) {
    const Triple& b = split.vertices()[split.fan_triangles()[f][k]];
    const T sum = T(b[0]) + T(b[1]) + T(b[2]);
    vx[k] = T(b[1]) / sum - T(center.x());
    vy[k] = T(b[2]) / sum - T(center.y());
  }
  const T twice_area = abs((vx[1] - vx[0]) * (vy[2] - vy[0]) - (vy[1] - vy[0]) * (vx[2] - vx[0]));
  int k = 0;
  for (int a = 0; a < g; ++a)
    for (int c = 0; c < g; ++c, ++k) {
      const T s = gx[a], t = (T(1.0) - s) * gx[c];
      x[k] = vx[0] + s * (vx[1] - vx[0]) + t * (vx[2] - vx[0]);
      y[k] = vy[0] + s * (vy[1] - vy[0]) + t * (vy[2] - vy[0]);
      w[k] = gw[a] * gw[c] * (T(1.0) - s) * twice_area;
    }
}

/// The reference matrices in long double, rounded once. Every integrand is a polynomial of degree
/// <= 8 on each fan triangle of the split: a collapsed 5 x 5 Gauss rule (degree 9 in the collapsed
/// direction) integrates it exactly, with nodes, split vertices (exact rationals) and the pieces in
/// long double. A double computation leaves round-off of ε Σ_q w_q |∂²B_i ∂²B_j| (x_q) in the
/// entries, much more than ε |K_ij| where the pieces cancel, and that error does not annihilate
/// linear functions: the biharmonic system amplifies it into an L2 error floor.
// The ten integral tables ∫ table_k table_lᵀ below, in long double (computed once).
const std::vector<MatrixL>& reference_sums() {
  static const std::vector<MatrixL> sums = [] {
  const Ws4Basis& basis = Ws4Basis::reference();
  const Ws4Split& split = basis.split();
  Real gx[5], gw[5];
  gauss_legendre_unit(5, gx, gw);
  constexpr int n = Ws4Basis::size, q = 25;
  // Six tables: value, ∂ξ, ∂η, ∂ξξ, ∂ξη, ∂ηη; sums[k][l] = ∫ table_k table_lᵀ for the pairs used.
  const auto& pairs = kPairs;
  std::vector<MatrixL> sums(10, MatrixL::Zero(n, n));
  MatrixL table[6];
  Eigen::Matrix<Real, 1, q> weights;
  std::vector<BasicPoly4<Real>> d(6 * n);
  // Only the B_i whose piece on the region is not zero enter its products (about a third of
  // them): the skipped terms are exact zeros, and the products cost a tenth.
  std::vector<int> active;
  int m = 0;
  int cached_region = -1;
  for (size_t f = 0; f < split.fan_triangles().size(); ++f) {
    const int r = split.fan_region()[f];
    if (r != cached_region) {
      m = active_pieces([&](int i) -> const BasicPoly4<Real>& { return basis.piece_extended(r, i); }, n, active, d);
      for (MatrixL& t : table) t.resize(m, q);
      cached_region = r;
    }
    Real x[q], y[q];
    fan_rule(basis, static_cast<int>(f), 5, gx, gw, x, y, weights.data());
    for (int k = 0; k < q; ++k)
      for (int j = 0; j < 6; ++j)
        for (int i = 0; i < m; ++i) table[j](i, k) = d[j * n + i](x[k], y[k]);
    for (int p = 0; p < 10; ++p) {
      const MatrixL local = table[pairs[p][0]] * weights.asDiagonal() * table[pairs[p][1]].transpose();
      for (int b = 0; b < m; ++b)
        for (int a = 0; a < m; ++a) sums[p](active[a], active[b]) += local(a, b);
    }
  }
  return sums;
  }();
  return sums;
}

/// The reference integrals from the integrals pair(p) of kPairs[p], p in [first, last) (a whole
/// group: the mass matrix 0, the gradient ones 1–3, the Hessian ones 4–9; the other members are
/// left empty), the transposed blocks through `transpose`.
template <class Matrix, class Pair, class Transpose>
ReferenceIntegrals<Matrix> from_pairs(int first, int last, Pair pair, Transpose transpose) {
  ReferenceIntegrals<Matrix> m;
  if (first == 0) m.mass = pair(0);
  if (first <= 1 && last >= 4) {
    m.grad[0][0] = pair(1);
    m.grad[0][1] = pair(2);
    m.grad[1][0] = transpose(m.grad[0][1]);
    m.grad[1][1] = pair(3);
  }
  if (last == 10) {
    int p = 4;
    for (int a = 0; a < 3; ++a)
      for (int b = a; b < 3; ++b) {
        m.hess[a][b] = pair(p++);
        // The diagonal blocks are already symmetric; assigning a matrix's own transpose to it aliases.
        if (b != a) m.hess[b][a] = transpose(m.hess[a][b]);
      }
  }
  return m;
}

/// The reference matrices from the sums, in double (rounded once) or long double.
template <class Matrix>
ReferenceIntegrals<Matrix> build() {
  using Scalar = typename Matrix::Scalar;
  const std::vector<MatrixL>& sums = reference_sums();
  const auto& pairs = kPairs;
  // A symmetric integrand gives an exactly symmetric matrix.
  auto rounded = [&](int p) {
    Matrix m = sums[p].template cast<Scalar>();
    if (pairs[p][0] == pairs[p][1]) m = m.template triangularView<Eigen::Upper>().toDenseMatrix().template selfadjointView<Eigen::Upper>();
    return m;
  };
  return from_pairs<Matrix>(0, 10, rounded, [](const Matrix& a) { return Matrix(a.transpose()); });
}

}  // namespace

const ReferenceIntegrals<Eigen::MatrixXd>& ws4_reference_integrals() {
  static const ReferenceIntegrals<Eigen::MatrixXd> m = build<Eigen::MatrixXd>();
  return m;
}

const ReferenceIntegrals<LongDoubleMatrix>& ws4_reference_integrals_extended() {
  static const ReferenceIntegrals<LongDoubleMatrix> m = build<LongDoubleMatrix>();
  return m;
}

namespace {

/// Total degree of the derivative table j of active_pieces (value, ∂x, ∂y, ∂xx, ∂xy, ∂yy)
/// of a quartic piece.
int derivative_degree(int j) { return j == 0 ? 4 : j < 3 ? 3 : 2; }


/// The ten integral tables of reference_sums() again, in double-double from pieces built in
/// double-double (the long double ones carry ≈ 1e-18 of their size after the cancellations of
/// the recurrence and the sums, which WS4's biharmonic conditioning turns into an L2 error of
/// 1e-12 at 9 226 DOFs, growing like h⁻⁴). Only the pairs [first_pair, last_pair) of kPairs, and
/// only the tables they use: a process needs the tables of its form alone (Poisson: 3 of the 10
/// integrals, plates: 6), each with the fewest exact Gauss points.
std::vector<DoubleDoubleMatrix> reference_sums_double_double(int first_pair, int last_pair) {
  using DD = DoubleDouble;
  const Ws4Basis& basis = Ws4Basis::reference();
  const Ws4Split& split = basis.split();
  static const std::vector<BasicPoly4<DD>> pieces = basis.pieces_double_double();
  bool needed[6] = {};
  for (int p = first_pair; p < last_pair; ++p) needed[kPairs[p][0]] = needed[kPairs[p][1]] = true;
  // Collapsed Gauss–Legendre with g x g points, g the fewest that integrate the products of the
  // requested pairs exactly: degree d in (x, y) becomes degree d + 1 in s (with the Jacobian
  // 1 - s) and d in t, exact when 2g - 1 >= d + 1. Pieces are quartics, so products of values
  // have degree 8 (g = 5), of first derivatives 6 (g = 4), of second derivatives 4 (g = 3).
  int max_degree = 0;
  for (int p = first_pair; p < last_pair; ++p)
    max_degree = std::max(max_degree, derivative_degree(kPairs[p][0]) + derivative_degree(kPairs[p][1]));
  const int g = (max_degree + 3) / 2;
  constexpr int n = Ws4Basis::size, kMaxPoints = 25;
  const int q = g * g;
  DD gx[5], gw[5];
  gauss_legendre_unit(g, gx, gw);
  // The fan triangles in a fixed number of chunks, summed separately (in parallel) and then added
  // in chunk order: the same sums whatever the number of threads.
  constexpr int kChunks = 8;
  const int num_fans = static_cast<int>(split.fan_triangles().size());
  std::vector<std::vector<std::vector<DD>>> chunk_sums(kChunks, std::vector<std::vector<DD>>(10, std::vector<DD>(n * n)));
#pragma omp parallel for schedule(dynamic, 1)
  for (int chunk = 0; chunk < kChunks; ++chunk) {
  std::vector<std::vector<DD>>& sums = chunk_sums[chunk];
  std::vector<int> active;
  std::vector<BasicPoly4<DD>> d(6 * n);
  std::vector<DD> table(6 * n * q);  // table[(j * n + a) * q + k]
  std::vector<double> value_hi(6 * n * q), value_lo(6 * n * q), weighted_hi(6 * n * q), weighted_lo(6 * n * q);
  DD weights[kMaxPoints];
  int m = 0, cached_region = -1;
  for (int f = num_fans * chunk / kChunks; f < num_fans * (chunk + 1) / kChunks; ++f) {
    const int r = split.fan_region()[f];
    if (r != cached_region) {
      m = active_pieces([&](int i) -> const BasicPoly4<DD>& { return pieces[r * n + i]; }, n, active, d);
      cached_region = r;
    }
    DD x[kMaxPoints], y[kMaxPoints];
    fan_rule(basis, f, g, gx, gw, x, y, weights);
    for (int k = 0; k < q; ++k)
      for (int j = 0; j < 6; ++j)
        if (needed[j])
          for (int i = 0; i < m; ++i) table[(j * n + i) * q + k] = d[j * n + i](x[k], y[k]);
    // (table · weight) once per function and point, as hi/lo doubles; then each integral is a
    // compensated dot product (exact products of the hi parts, the rest in the error term).
    for (int j = 0; j < 6; ++j)
      for (int i = 0; i < (needed[j] ? m : 0); ++i)
        for (int kk = 0; kk < q; ++kk) {
          const DD& v = table[(j * n + i) * q + kk];
          const DD vw = v * weights[kk];
          value_hi[(j * n + i) * q + kk] = v.hi;
          value_lo[(j * n + i) * q + kk] = v.lo;
          weighted_hi[(j * n + i) * q + kk] = vw.hi;
          weighted_lo[(j * n + i) * q + kk] = vw.lo;
        }
    for (int p = first_pair; p < last_pair; ++p) {
      const int t0 = kPairs[p][0], t1 = kPairs[p][1];
      for (int b = 0; b < m; ++b) {
        const double* bh = &value_hi[(t1 * n + b) * q];
        const double* bl = &value_lo[(t1 * n + b) * q];
        // A symmetric pair needs only a <= b (the other half is mirrored below).
        for (int a = 0; a < (t0 == t1 ? b + 1 : m); ++a) {
          const double* ah = &weighted_hi[(t0 * n + a) * q];
          const double* al = &weighted_lo[(t0 * n + a) * q];
          double sum = 0, err = 0;
          for (int kk = 0; kk < q; ++kk) {
            const DD prod = dd_detail::two_prod(ah[kk], bh[kk]);
            const DD t = dd_detail::two_sum(sum, prod.hi);
            sum = t.hi;
            err += t.lo + prod.lo + ah[kk] * bl[kk] + al[kk] * bh[kk];
          }
          // Stored at (row, column) = (active[a], active[b]); for a symmetric pair row <= column
          // since active is increasing.
          sums[p][active[b] * n + active[a]] += dd_detail::quick_two_sum(sum, err);
        }
      }
    }
  }
  }
  std::vector<std::vector<DD>>& sums = chunk_sums[0];
  for (int chunk = 1; chunk < kChunks; ++chunk)
    for (int p = 0; p < 10; ++p)
      for (int i = 0; i < n * n; ++i) sums[p][i] += chunk_sums[chunk][p][i];
  std::vector<DoubleDoubleMatrix> out(10);
  for (int p = first_pair; p < last_pair; ++p) {
    out[p].resize(n, n);
    for (int b = 0; b < n; ++b)
      for (int a = 0; a < n; ++a) {
        // A symmetric integrand gives an exactly symmetric matrix (upper triangle mirrored).
        const bool mirror = kPairs[p][0] == kPairs[p][1] && a > b;
        out[p].set(a, b, mirror ? sums[p][a * n + b] : sums[p][b * n + a]);
      }
  }
  return out;
}

DoubleDoubleMatrix transposed(const DoubleDoubleMatrix& m) {
  DoubleDoubleMatrix t;
  t.hi = m.hi.transpose();
  t.lo = m.lo.transpose();
  return t;
}

}  // namespace

const ReferenceIntegrals<DoubleDoubleMatrix>& ws4_reference_integrals_double_double(BilinearForm form) {
  // The group of kPairs `form` uses: 0 the mass matrix, 1 the gradient ones, 2 the Hessian ones
  // (bilaplace and hessian forms); the other members are left empty.
  const int group = form == BilinearForm::mass ? 0 : form == BilinearForm::laplace ? 1 : 2;
  auto build_group = [](int group) {
    const int first[3] = {0, 1, 4}, last[3] = {1, 4, 10};
    const std::vector<DoubleDoubleMatrix> sums = reference_sums_double_double(first[group], last[group]);
    return from_pairs<DoubleDoubleMatrix>(first[group], last[group], [&](int p) { return sums[p]; }, transposed);
  };
  switch (group) {
    case 0: {
      static const ReferenceIntegrals<DoubleDoubleMatrix> mass = build_group(0);
      return mass;
    }
    case 1: {
      static const ReferenceIntegrals<DoubleDoubleMatrix> grad = build_group(1);
      return grad;
    }
    default: {
      static const ReferenceIntegrals<DoubleDoubleMatrix> hess = build_group(2);
      return hess;
    }
  }
}

}  // namespace iga::ws4
