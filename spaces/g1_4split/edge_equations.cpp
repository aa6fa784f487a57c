#include "spaces/g1_4split/edge_equations.hpp"

#include <algorithm>
#include <cmath>

namespace iga {

std::vector<int> side_row(const SplitBSpline& b, int local_edge, int row) {
  const int m = b.last(), n = m + 1;
  std::vector<int> out(n);
  for (int i = 0; i <= m; ++i) {
    int u = 0, v = 0;
    switch (local_edge) {
      case 0: u = i, v = row; break;
      case 1: u = m - row, v = i; break;
      case 2: u = m - i, v = m - row; break;
      default: u = row, v = m - i; break;
    }
    out[i] = u + v * n;
  }
  return out;
}

std::vector<int> corner_block(const SplitBSpline& b, int corner) {
  // Corner c is the start of side c: positions 0, 1 of rows 0 and 1.
  const auto r0 = side_row(b, corner, 0), r1 = side_row(b, corner, 1);
  return {r0[0], r0[1], r1[0], r1[1]};
}

std::vector<int> interior_indices(const SplitBSpline& b) {
  const int m = b.last(), n = m + 1;
  std::vector<int> out;
  for (int j = 2; j <= m - 2; ++j)
    for (int i = 2; i <= m - 2; ++i) out.push_back(i + j * n);
  return out;
}

std::vector<std::array<std::vector<int>, 2>> split_edge_rows(const QuadTopology& t, const SplitBSpline& b, int e) {
  const QuadEdge& edge = t.edge(e);
  const int fs = b.face_size();
  std::vector<std::array<std::vector<int>, 2>> out;
  for (const QuadSide& s : edge.sides) {
    std::array<std::vector<int>, 2> rows;
    const bool forward = t.face(s.face)[s.local_edge] == edge.g0;
    for (int r = 0; r < 2; ++r) {
      rows[r] = side_row(b, s.local_edge, r);
      if (!forward) std::reverse(rows[r].begin(), rows[r].end());
      for (int& x : rows[r]) x += s.face * fs;
    }
    out.push_back(std::move(rows));
  }
  return out;
}

namespace {

/// Row of the G1 residual functional q_0(t) + q_1(t) - a(t) p'(t) (derivative `order` in t) at t
/// on half `half`, over the 4(m+1) edge columns in edge_equations order.
Eigen::RowVectorXd g1_functional(const SplitBSpline& b, const SplitGluing& a, double t, int half, int order) {
  const int n = b.size();
  const double kappa = b.derivatives(0.0, 1, 0)(1, 1);  // N_1'(0): inward derivative = kappa (row1 - row0)
  const Eigen::MatrixXd N = b.derivatives(t, order + 2, half);
  Eigen::RowVectorXd row = Eigen::RowVectorXd::Zero(4 * n);
  for (int s = 0; s < 2; ++s) {
    row.segment(2 * s * n + n, n) += kappa * N.row(order);
    row.segment(2 * s * n, n) -= kappa * N.row(order);
  }
  // d^order/dt^order (a p') = sum_l binom(order, l) a^{(l)} p^{(order - l + 1)}.
  for (int l = 0; l <= order; ++l) {
    const double binom = (l == 0 || l == order) ? 1.0 : double(order);
    row.segment(0, n) -= binom * a.eval(t, l, half) * N.row(order - l + 1);
  }
  return row;
}

}  // namespace

Eigen::MatrixXd edge_equations(const QuadTopology& t, const SplitBSpline& b, const SplitGluing& a, int e,
                               std::vector<int>& columns) {
  const auto rows = split_edge_rows(t, b, e);
  const int n = b.size(), k = b.degree(), pts = k + 4;
  columns.clear();
  for (int s = 0; s < 2; ++s)
    for (int r = 0; r < 2; ++r) columns.insert(columns.end(), rows[s][r].begin(), rows[s][r].end());
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(n + 2 * pts, 4 * n);
  for (int i = 0; i < n; ++i) {
    M(i, i) = 1.0;
    M(i, 2 * n + i) = -1.0;
  }
  const double pi = std::acos(-1.0);
  for (int h = 0; h < 2; ++h)
    for (int q = 0; q < pts; ++q) {
      // Chebyshev points inside the half.
      const double x = 0.5 * (1 - std::cos(pi * (q + 0.5) / pts));
      M.row(n + h * pts + q) = g1_functional(b, a, 0.5 * (h + x), h, 0);
    }
  return M;
}

Eigen::MatrixXd vertex_equations(const QuadTopology& t, const SplitBSpline& b, const SplitGluing& a, int e, int end,
                                 std::vector<int>& columns) {
  const auto rows = split_edge_rows(t, b, e);
  const int n = b.size(), m = b.last();
  const double te = end == 0 ? 0.0 : 1.0;
  const int p0 = end == 0 ? 0 : m - 1;  // positions of the corner block along the edge
  std::vector<int> local;  // positions within the 4n edge columns
  columns.clear();
  for (int s = 0; s < 2; ++s)
    for (int r = 0; r < 2; ++r)
      for (int i = p0; i <= p0 + 1; ++i) {
        local.push_back((2 * s + r) * n + i);
        columns.push_back(rows[s][r][i]);
      }
  std::vector<Eigen::RowVectorXd> eq;
  for (int i = p0; i <= p0 + 1; ++i) {
    Eigen::RowVectorXd c0 = Eigen::RowVectorXd::Zero(4 * n);
    c0(i) = 1.0;
    c0(2 * n + i) = -1.0;
    eq.push_back(c0);
  }
  eq.push_back(g1_functional(b, a, te, end, 0));
  if (std::abs(a.eval(te, 0, end)) < 1e-12) eq.push_back(g1_functional(b, a, te, end, 1));
  Eigen::MatrixXd M(eq.size(), local.size());
  for (std::size_t r = 0; r < eq.size(); ++r)
    for (std::size_t c = 0; c < local.size(); ++c) M(r, c) = eq[r](local[c]);
  return M;
}

}  // namespace iga
