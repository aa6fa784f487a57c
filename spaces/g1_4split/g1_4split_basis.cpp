#include "spaces/g1_4split/g1_4split_basis.hpp"

#include <Eigen/Dense>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <map>

#include "spaces/g1_4split/edge_equations.hpp"
#include "spaces/g1_4split/line_gluing.hpp"

namespace iga {

namespace {

/// Orthonormal basis of the numerical nullspace of M (columns).
Eigen::MatrixXd nullspace(const Eigen::MatrixXd& M) {
  if (M.rows() == 0) return Eigen::MatrixXd::Identity(M.cols(), M.cols());
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(M, Eigen::ComputeFullV);
  const Eigen::VectorXd& s = svd.singularValues();
  const double tol = 1e-10 * std::max(s.size() ? s(0) : 0.0, 1e-300);
  int rank = 0;
  for (int i = 0; i < s.size(); ++i)
    if (s(i) > tol) ++rank;
  return svd.matrixV().rightCols(M.cols() - rank);
}

/// One interior edge's equations split into the corner columns at each end and the strip.
struct EdgeSystem {
  Eigen::MatrixXd M;                 ///< all equations over `columns`
  std::vector<int> columns;          ///< global broken indices
  std::vector<int> strip;            ///< positions (in columns) of the strip unknowns
  std::vector<int> end_corner[2];    ///< positions of the corner unknowns at g0 / g1
  Eigen::MatrixXd M_strip;
  Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> solver;
};

EdgeSystem edge_system(const QuadTopology& t, const SplitBSpline& b, const SplitGluing& a, int e) {
  EdgeSystem s;
  s.M = edge_equations(t, b, a, e, s.columns);
  const int n = b.size(), m = b.last();
  for (int p = 0; p < static_cast<int>(s.columns.size()); ++p) {
    const int i = p % n;
    if (i <= 1) s.end_corner[0].push_back(p);
    else if (i >= m - 1) s.end_corner[1].push_back(p);
    else s.strip.push_back(p);
  }
  s.M_strip.resize(s.M.rows(), static_cast<Eigen::Index>(s.strip.size()));
  for (std::size_t c = 0; c < s.strip.size(); ++c) s.M_strip.col(c) = s.M.col(s.strip[c]);
  s.solver.compute(s.M_strip);
  return s;
}

}  // namespace

int nullspace_dimension(const Eigen::MatrixXd& M) {
  if (M.rows() == 0) return static_cast<int>(M.cols());
  Eigen::BDCSVD<Eigen::MatrixXd> svd(M);
  const Eigen::VectorXd& s = svd.singularValues();
  const double tol = 1e-10 * std::max(s.size() ? s(0) : 0.0, 1e-300);
  int rank = 0;
  for (int i = 0; i < s.size(); ++i)
    if (s(i) > tol) ++rank;
  return static_cast<int>(M.cols()) - rank;
}

std::vector<double> symmetric_vertex_values(const QuadTopology& t, const std::vector<double>& boundary_angles) {
  std::vector<double> A(t.num_vertices(), 0.0);
  for (int v = 0; v < t.num_vertices(); ++v) {
    const int F = t.vertex_faces(v);
    if (F == 0) continue;
    if (!t.vertex_on_boundary(v) || boundary_angles.empty()) {
      A[v] = vertex_gluing_value(F, t.vertex_on_boundary(v));
    } else {
      A[v] = 2 * std::cos(boundary_angles[v] / F);
      if (std::abs(A[v]) < 1e-9) A[v] = 0.0;  // a straight boundary point with 2 faces is crossing
    }
  }
  return A;
}

std::vector<SplitGluing> symmetric_gluing(const QuadTopology& t, Blending blending,
                                          const std::vector<double>& boundary_angles) {
  const std::vector<double> A = symmetric_vertex_values(t, boundary_angles);
  if (blending == Blending::lines) return line_gluing(t, A);
  std::vector<SplitGluing> g(t.num_edges());
  for (int e = 0; e < t.num_edges(); ++e) {
    const QuadEdge& edge = t.edge(e);
    if (edge.boundary()) continue;
    g[e] = SplitGluing::symmetric(A[edge.g0], A[edge.g1], blending);
  }
  return g;
}

std::vector<SplitGluing> inherited_gluing(const QuadTopology& coarse, const std::vector<SplitGluing>& gluing,
                                         const QuadTopology& fine) {
  std::vector<SplitGluing> out(fine.num_edges());
  for (int e = 0; e < fine.num_edges(); ++e) {
    const QuadEdge& edge = fine.edge(e);
    if (edge.boundary()) continue;
    const QuadSide side = edge.sides[0];
    const int j = side.local_edge;
    if (j == 1 || j == 2) continue;  // inside a coarse face: a ≡ 0
    const int f = side.face / 4, c = side.face % 4;
    const int parent_local = j == 0 ? c : (c + 3) % 4;
    const double s0 = j == 0 ? 0.0 : 0.5;  // parent side parameter at the fine side's start
    const int E = coarse.face_edge(f, parent_local);
    const bool parent_forward = coarse.face(f)[parent_local] == coarse.edge(E).g0;
    const bool fine_forward = fine.face(side.face)[j] == edge.g0;
    auto t_of = [&](double tau) {
      const double sigma = fine_forward ? tau : 1.0 - tau;
      const double s = s0 + 0.5 * sigma;
      return parent_forward ? s : 1.0 - s;
    };
    out[e] = gluing[E].restricted(t_of(0.0), t_of(1.0));
  }
  return out;
}

int crossing_vertex_with_slope(const QuadTopology& t, const std::vector<SplitGluing>& gluing) {
  return twist_incompatible_vertex(t, gluing);
}

Eigen::SparseMatrix<double> global_constraints(const QuadTopology& t, const std::vector<SplitGluing>& gluing,
                                               const SplitBSpline& b) {
  std::vector<Eigen::Triplet<double>> trip;
  int rows = 0;
  for (int e = 0; e < t.num_edges(); ++e) {
    if (t.edge(e).boundary()) continue;
    std::vector<int> cols;
    const Eigen::MatrixXd M = edge_equations(t, b, gluing[e], e, cols);
    for (int r = 0; r < M.rows(); ++r)
      for (int c = 0; c < M.cols(); ++c)
        if (M(r, c) != 0.0) trip.emplace_back(rows + r, cols[c], M(r, c));
    rows += static_cast<int>(M.rows());
  }
  Eigen::SparseMatrix<double> C(rows, t.num_faces() * b.face_size());
  C.setFromTriplets(trip.begin(), trip.end());
  return C;
}

int g14_dimension_formula(const QuadTopology& t, const std::vector<SplitGluing>& gluing, int k, int r) {
  const SplitBSpline b(k, r);
  int sum = 0;
  for (int e = 0; e < t.num_edges(); ++e) {
    if (t.edge(e).boundary()) {
      sum += 4 * k - 2 * r - 6;
      continue;
    }
    std::vector<int> cols;
    sum += nullspace_dimension(edge_equations(t, b, gluing[e], e, cols)) - 1 - 9;
  }
  int crossing = 0;
  for (int v = 0; v < t.num_vertices(); ++v) {
    if (t.vertex_on_boundary(v)) continue;
    bool all = true;
    for (int e : t.vertex_edges(v)) all = all && std::abs(gluing[e].eval(t.edge(e).g0 == v ? 0.0 : 1.0, 0, t.edge(e).g0 == v ? 0 : 1)) < 1e-12;
    crossing += all ? 1 : 0;
  }
  const int inner = 2 * k - r - 3;
  return sum + 3 * t.num_vertices() + 4 * t.num_faces() + crossing + inner * inner * t.num_faces();
}

G14Basis build_g14_basis(const QuadTopology& t, const std::vector<SplitGluing>& gluing, int k, int r) {
  G14Basis basis;
  basis.bspline = SplitBSpline(k, r);
  const SplitBSpline& b = basis.bspline;
  const int fs = b.face_size(), m = b.last();
  std::vector<Eigen::Triplet<double>> trip;
  int col = 0;
  auto add = [&](const std::map<int, double>& v) {
    double big = 0.0;
    for (const auto& [i, x] : v) big = std::max(big, std::abs(x));
    for (const auto& [i, x] : v)
      if (std::abs(x) > 1e-14 * big) trip.emplace_back(i, col, x);
    ++col;
  };

  std::vector<EdgeSystem> systems(t.num_edges());
  for (int e = 0; e < t.num_edges(); ++e)
    if (!t.edge(e).boundary()) systems[e] = edge_system(t, b, gluing[e], e);

  // Vertex functions: a basis of the admissible corner data, lifted along every interior edge.
  for (int v = 0; v < t.num_vertices(); ++v) {
    std::vector<int> vc;
    for (const auto& [f, c] : t.vertex_corners(v))
      for (int i : corner_block(b, c)) vc.push_back(f * fs + i);
    std::map<int, int> pos;
    for (std::size_t i = 0; i < vc.size(); ++i) pos[vc[i]] = static_cast<int>(i);
    std::vector<Eigen::RowVectorXd> eqs;
    for (int e : t.vertex_edges(v)) {
      if (t.edge(e).boundary()) continue;
      std::vector<int> cols;
      const Eigen::MatrixXd M = vertex_equations(t, b, gluing[e], e, t.edge(e).g0 == v ? 0 : 1, cols);
      for (int rr = 0; rr < M.rows(); ++rr) {
        Eigen::RowVectorXd row = Eigen::RowVectorXd::Zero(static_cast<Eigen::Index>(vc.size()));
        for (std::size_t c = 0; c < cols.size(); ++c) row(pos.at(cols[c])) += M(rr, c);
        eqs.push_back(row);
      }
    }
    Eigen::MatrixXd E(static_cast<Eigen::Index>(eqs.size()), static_cast<Eigen::Index>(vc.size()));
    for (std::size_t rr = 0; rr < eqs.size(); ++rr) E.row(rr) = eqs[rr];
    const Eigen::MatrixXd H = nullspace(E);
    std::vector<std::map<int, double>> lifted;
    for (int h = 0; h < H.cols(); ++h) {
      std::map<int, double> fn;
      for (std::size_t i = 0; i < vc.size(); ++i) fn[vc[i]] += H(i, h);
      for (int e : t.vertex_edges(v)) {
        if (t.edge(e).boundary()) continue;
        const EdgeSystem& s = systems[e];
        const int end = t.edge(e).g0 == v ? 0 : 1;
        Eigen::VectorXd rhs = Eigen::VectorXd::Zero(s.M.rows());
        for (int p : s.end_corner[end]) rhs -= s.M.col(p) * H(pos.at(s.columns[p]), h);
        const Eigen::VectorXd x = s.solver.solve(rhs);
        const double residual = (s.M_strip * x - rhs).norm();
        if (residual > 1e-9 * std::max(1.0, rhs.norm()))
          throw NotSeparable(e, v,
                             "the corner data at vertex " + std::to_string(v) + " cannot be lifted along the edge " +
                                 std::to_string(t.edge(e).g0) + "-" + std::to_string(t.edge(e).g1) + " (residual " +
                                 std::to_string(residual) + ")");
        for (std::size_t c = 0; c < s.strip.size(); ++c) fn[s.columns[s.strip[c]]] += x(c);
      }
      lifted.push_back(std::move(fn));
    }
    // Orthonormalize the lifted functions (same span): near a vertex whose gluing value is small
    // but not zero, twist data force second tangential derivatives ~ 1/A along the edge, and the
    // raw lifts would be badly scaled and nearly dependent.
    std::map<int, int> rows;
    for (const auto& fn : lifted)
      for (const auto& [i, x] : fn) rows.emplace(i, 0);
    int r = 0;
    for (auto& [i, pos] : rows) pos = r++;
    Eigen::MatrixXd L = Eigen::MatrixXd::Zero(r, static_cast<Eigen::Index>(lifted.size()));
    for (std::size_t c = 0; c < lifted.size(); ++c)
      for (const auto& [i, x] : lifted[c]) L(rows.at(i), c) = x;
    const Eigen::MatrixXd Q = Eigen::JacobiSVD<Eigen::MatrixXd>(L, Eigen::ComputeThinU).matrixU();
    for (int c = 0; c < Q.cols(); ++c) {
      std::map<int, double> fn;
      for (const auto& [i, pos] : rows) fn[i] = Q(pos, c);
      add(fn);
    }
  }
  basis.vertex_functions = col;

  // Edge functions: strip solutions with zero corner data.
  for (int e = 0; e < t.num_edges(); ++e) {
    const QuadEdge& edge = t.edge(e);
    if (edge.boundary()) {
      const QuadSide s = edge.sides[0];
      for (int rr = 0; rr < 2; ++rr) {
        const std::vector<int> row = side_row(b, s.local_edge, rr);
        for (int i = 2; i <= m - 2; ++i) add({{s.face * fs + row[i], 1.0}});
      }
      continue;
    }
    const EdgeSystem& s = systems[e];
    const Eigen::MatrixXd N = nullspace(s.M_strip);
    for (int c = 0; c < N.cols(); ++c) {
      std::map<int, double> fn;
      for (std::size_t i = 0; i < s.strip.size(); ++i) fn[s.columns[s.strip[i]]] += N(i, c);
      add(fn);
    }
  }
  basis.edge_functions = col - basis.vertex_functions;

  // Face functions.
  const std::vector<int> inner = interior_indices(b);
  for (int f = 0; f < t.num_faces(); ++f)
    for (int i : inner) add({{f * fs + i, 1.0}});
  basis.face_functions = col - basis.vertex_functions - basis.edge_functions;

  basis.functions.resize(t.num_faces() * fs, col);
  basis.functions.setFromTriplets(trip.begin(), trip.end());

  // Per-face extraction.
  std::vector<std::vector<Eigen::Triplet<double>>> local(t.num_faces());
  basis.face_dofs.assign(t.num_faces(), {});
  for (int c = 0; c < basis.functions.outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(basis.functions, c); it; ++it) {
      const int f = static_cast<int>(it.row()) / fs;
      auto& d = basis.face_dofs[f];
      if (d.empty() || d.back() != c) d.push_back(c);
      local[f].emplace_back(static_cast<int>(it.row()) % fs, static_cast<int>(d.size()) - 1, it.value());
    }
  basis.extraction.resize(t.num_faces());
  for (int f = 0; f < t.num_faces(); ++f) {
    basis.extraction[f].resize(fs, static_cast<Eigen::Index>(basis.face_dofs[f].size()));
    basis.extraction[f].setFromTriplets(local[f].begin(), local[f].end());
  }
  return basis;
}

}  // namespace iga
