#include "spaces/ws4/ws4_hermite_transform.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <initializer_list>
#include <stdexcept>
#include <vector>

#include "spaces/ws4/ws4_dof_layout.hpp"
#include "spaces/ws4/ws4_edge_traces.hpp"

namespace iga::ws4 {

namespace {

using Real = long double;
using Vec2L = Eigen::Matrix<Real, 2, 1>;
using namespace dof_layout;

Real power(Real x, int k) {
  Real p = 1;
  for (int i = 0; i < k; ++i) p *= x;
  return p;
}

/// Up to three derivative directions (repeats allowed).
struct Directions {
  Vec2L w[3];
  int count = 0;
  Directions() = default;
  Directions(std::initializer_list<Vec2L> list) {
    for (const Vec2L& v : list) w[count++] = v;
  }
  Directions(int times, const Vec2L& v) { then(times, v); }
  Directions& then(int times, const Vec2L& v) {
    for (int i = 0; i < times; ++i) w[count++] = v;
    return *this;
  }
};

/// Rows of T_K for one element: each functional as a combination of the element's DOFs. Every
/// contribution is added straight into the row (a functional touches at most 26 of the 51 DOFs).
class FunctionalRows {
 public:
  explicit FunctionalRows(const ElementDofGeometry& g) : g_(g) {
    for (int a = 0; a < 3; ++a) {
      x_[a] = g.corner[a].cast<Real>();
      frame_inverse_[a] = g.frame[a].cast<Real>().inverse();
    }
  }

  const Vec2L& x(int a) const { return x_[a]; }

  /// row += weight × D_{w_1} … D_{w_k} u at corner a (physical directions w).
  void add_vertex_derivative(Real* row, Real weight, int a, const Directions& w) const {
    Vec2L c[3];  // the directions in the corner's frame: w = c_1 d1 + c_2 d2
    const int k = w.count;
    for (int m = 0; m < k; ++m) c[m] = frame_inverse_[a] * w.w[m];
    weight /= power(g_.vertex_scale[a], k);
    for (int choice = 0; choice < (1 << k); ++choice) {  // bit m set: direction m contributes its d2 part
      Real product = weight;
      int n1 = 0, n2 = 0;
      for (int m = 0; m < k; ++m) {
        const bool second = (choice >> m) & 1;
        product *= c[m](second ? 1 : 0);
        ++(second ? n2 : n1);
      }
      row[10 * a + vertex_index[n1][n2]] += product;
    }
  }

  /// row += ρ = D_d^r u(q) at q = P_e + σ (P_{e+1} − P_e) with d = (opposite corner) − q (notes
  /// §8.3): Σ_m C(r, m) α^m β^{r−m} D_t^{r−m} D_n^m u(q), α = d·n, β = d·t, and D_t^j = L^{−j} d^j/ds^j
  /// of the trace g_m.
  void add_edge_functional(Real* row, int e, double sigma, int r) const {
    const bool reversed = g_.edge_reversed[e];
    const int a = reversed ? (e + 1) % 3 : e, b = reversed ? e : (e + 1) % 3;
    const double s = reversed ? 1.0 - sigma : sigma;  // exact for σ ∈ {¼, ½, ¾}
    Edge edge{e, a, b, (x_[b] - x_[a]).norm(), {}, {}};
    edge.t = (x_[b] - x_[a]) / edge.length;
    edge.n = Vec2L(-edge.t.y(), edge.t.x());
    const Vec2L q = x_[a] + Real(s) * (x_[b] - x_[a]);
    const Vec2L d = x_[(e + 2) % 3] - q;
    const Real alpha = d.dot(edge.n), beta = d.dot(edge.t);
    Real binomial = 1;
    for (int m = 0; m <= r; ++m) {
      const int j = r - m;
      add_trace_derivative(row, binomial * power(alpha, m) * power(beta / edge.length, j), edge, m, j, s);
      binomial = binomial * (r - m) / (m + 1);
    }
  }

 private:
  struct Edge {
    int local, a, b;  // local edge, corners at its global start and end
    Real length;
    Vec2L t, n;
  };

  /// row += weight × g_m^{(j)}(s) of the trace g_m(s) = ∂_n^m u(x_a + s (x_b − x_a)).
  void add_trace_derivative(Real* row, Real weight, const Edge& edge, int m, int j, double s) const {
    if (j == 0) return add_edge_dof(row, weight, edge, m, s);
    const EdgeTraceData& data = edge_trace_data(m);
    const std::vector<long double>& map = edge_trace_map(m, j, s);
    int k = 0;
    for (const int corner : {edge.a, edge.b}) {
      // g_m^{(i)} at an end = L^i D_t^i D_n^m u there, i < data.end_derivatives <= 4 − m.
      Real length_power = 1;
      for (int i = 0; i < data.end_derivatives; ++i, length_power *= edge.length) {
        const Real w = weight * map[k++] * length_power;
        add_vertex_derivative(row, w, corner, Directions(i, edge.t).then(m, edge.n));
      }
    }
    for (const double si : data.interior_s) add_edge_dof(row, weight * map[k++], edge, m, si);
  }

  /// row += weight × ∂_n^m u(e(s)) at an edge DOF point.
  void add_edge_dof(Real* row, Real weight, const Edge& edge, int m, double s) const {
    for (int k = 0; k < 6; ++k)
      if (edge_order[k] == m && edge_s[k] == s) {
        row[first_edge_dof + 6 * edge.local + k] += weight / power(g_.edge_scale[edge.local], m);
        return;
      }
    throw std::logic_error("WS4 extraction: no edge DOF for this trace value");
  }

  const ElementDofGeometry& g_;
  std::array<Vec2L, 3> x_;
  std::array<Eigen::Matrix<Real, 2, 2>, 3> frame_inverse_;
};

}  // namespace

Matrix51L ws4_functionals_from_dofs(const ElementDofGeometry& geometry) {
  const FunctionalRows rows(geometry);
  Matrix51L t = Matrix51L::Zero();
  for (int a = 0; a < 3; ++a) {
    // Paper numbering: corner a with u = P_{a+1} − P_a and v = P_{a+2} − P_a (indices mod 3).
    const Vec2L u = rows.x((a + 1) % 3) - rows.x(a), v = rows.x((a + 2) % 3) - rows.x(a);
    rows.add_vertex_derivative(t.row(a).data(), 1, a, Directions());
    rows.add_vertex_derivative(t.row(3 + 2 * a).data(), 1, a, {u});
    rows.add_vertex_derivative(t.row(4 + 2 * a).data(), 1, a, {v});
    rows.add_vertex_derivative(t.row(9 + 2 * a).data(), 1, a, {u, u});
    rows.add_vertex_derivative(t.row(10 + 2 * a).data(), 1, a, {v, v});
    rows.add_vertex_derivative(t.row(15 + a).data(), 1, a, {u, v});
    rows.add_vertex_derivative(t.row(18 + 2 * a).data(), 1, a, {u, u, u});
    rows.add_vertex_derivative(t.row(19 + 2 * a).data(), 1, a, {v, v, v});
    rows.add_vertex_derivative(t.row(24 + 2 * a).data(), 1, a, {u, u, v});
    rows.add_vertex_derivative(t.row(25 + 2 * a).data(), 1, a, {v, v, u});
  }
  // Edge functionals: ρ31+e at the midpoint (order 1), ρ46+e (order 3); at the quarter points
  // near the edge's start / end, order 2: ρ34/ρ37, ρ36/ρ39, ρ38/ρ35 for e = 0, 1, 2, order 3: +6.
  const int near_start[3] = {33, 35, 37}, near_end[3] = {36, 38, 34};
  for (int e = 0; e < 3; ++e) {
    rows.add_edge_functional(t.row(30 + e).data(), e, 0.5, 1);
    rows.add_edge_functional(t.row(45 + e).data(), e, 0.5, 3);
    for (int r : {2, 3}) {
      rows.add_edge_functional(t.row(near_start[e] + 6 * (r - 2)).data(), e, 0.25, r);
      rows.add_edge_functional(t.row(near_end[e] + 6 * (r - 2)).data(), e, 0.75, r);
    }
  }
  for (int k = 0; k < 3; ++k) t(48 + k, first_interior_dof + k) = 1;  // ρ49..51 = interior values
  return t;
}

Eigen::MatrixXd ws4_exact_extraction(const ElementDofGeometry& geometry) {
  // Both factors are sparse (A⁻¹: 744 nonzeros, T_K: ≈ 345), so the product in long double, rounded
  // once, costs ≈ 5k operations instead of the 51³ of a dense double product, and C_K is as exact
  // as a double matrix can be (clamped plate, level 4 of ws4-biharmonic.yaml: L2 3.4e-12 → 2.8e-12).
  struct Nonzero {
    int index;
    Real value;
  };
  static const std::vector<std::vector<Nonzero>> inverse_rows = [] {
    const Matrix51L& inverse = ws4_coefficients_from_functionals();
    std::vector<std::vector<Nonzero>> rows(51);
    for (int i = 0; i < 51; ++i)
      for (int j = 0; j < 51; ++j)
        if (inverse(i, j) != 0) rows[i].push_back({j, inverse(i, j)});
    return rows;
  }();
  const Matrix51L t = ws4_functionals_from_dofs(geometry);
  // The nonzeros of T_K row by row, in one flat array (no allocation per element).
  std::array<Nonzero, 51 * 51> t_nonzeros;
  std::array<int, 52> t_start;
  int count = 0;
  for (int j = 0; j < 51; ++j) {
    t_start[j] = count;
    for (int m = 0; m < 51; ++m)
      if (t(j, m) != 0) t_nonzeros[count++] = {m, t(j, m)};
  }
  t_start[51] = count;
  Eigen::MatrixXd c(51, 51);
  Real row[51];
  for (int i = 0; i < 51; ++i) {
    std::fill(row, row + 51, Real(0));
    for (const Nonzero& a : inverse_rows[i])
      for (int e = t_start[a.index]; e < t_start[a.index + 1]; ++e)
        row[t_nonzeros[e].index] += a.value * t_nonzeros[e].value;
    for (int m = 0; m < 51; ++m) c(i, m) = static_cast<double>(row[m]);
  }
  return c;
}

}  // namespace iga::ws4
