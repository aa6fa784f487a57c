#include "spaces/g1_4split/g14_local_problems.hpp"

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <string>

#include "spaces/g1_4split/edge_equations.hpp"
#include "spaces/g1_4split/g1_4split_basis.hpp"

namespace iga {

Eigen::MatrixXd numerical_nullspace(const Eigen::MatrixXd& M) {
  if (M.rows() == 0) return Eigen::MatrixXd::Identity(M.cols(), M.cols());
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(M, Eigen::ComputeFullV);
  const Eigen::VectorXd& s = svd.singularValues();
  const double tol = 1e-10 * std::max(s.size() ? s(0) : 0.0, 1e-300);
  int rank = 0;
  for (int i = 0; i < s.size(); ++i)
    if (s(i) > tol) ++rank;
  return svd.matrixV().rightCols(M.cols() - rank);
}

std::vector<std::pair<int, double>> kept_entries(const BrokenFunction& fn) {
  double big = 0.0;
  for (const auto& [i, x] : fn) big = std::max(big, std::abs(x));
  std::vector<std::pair<int, double>> out;
  for (const auto& [i, x] : fn)
    if (std::abs(x) > 1e-14 * big) out.emplace_back(i, x);
  return out;
}

void G14Numbering::face_functions(const QuadTopology& t, int f, std::vector<int>& out) const {
  out.clear();
  std::array<int, 4> v = t.face(f), e;
  for (int j = 0; j < 4; ++j) e[j] = t.face_edge(f, j);
  std::sort(v.begin(), v.end());
  std::sort(e.begin(), e.end());
  // Vertex ranges precede edge ranges, which precede face ranges: sorted entities give sorted columns.
  for (int x : v)
    for (int c = vertex_first[x]; c < vertex_first[x + 1]; ++c) out.push_back(c);
  for (int x : e)
    for (int c = edge_first[x]; c < edge_first[x + 1]; ++c) out.push_back(c);
  const int first = edge_first.back() + f * per_face;
  for (int c = first; c < first + per_face; ++c) out.push_back(c);
}

G14FaceExtractions::G14FaceExtractions(int face_size, const std::vector<int>& slot,
                                       std::vector<std::vector<int>> face_functions)
    : fs_(face_size), slot_(slot), dofs_(std::move(face_functions)), trip_(dofs_.size()) {}

void G14FaceExtractions::add(int column, int index, double value) {
  const int s = slot_[index / fs_];
  if (s < 0) return;
  const std::vector<int>& d = dofs_[s];
  const int j = static_cast<int>(std::lower_bound(d.begin(), d.end(), column) - d.begin());
  trip_[s].emplace_back(index % fs_, j, value);
}

std::vector<Eigen::SparseMatrix<double>> G14FaceExtractions::finish() const {
  std::vector<Eigen::SparseMatrix<double>> out(dofs_.size());
  for (std::size_t s = 0; s < dofs_.size(); ++s) {
    out[s].resize(fs_, static_cast<Eigen::Index>(dofs_[s].size()));
    out[s].setFromTriplets(trip_[s].begin(), trip_[s].end());
  }
  return out;
}

G14EdgeSystem G14LocalProblems::edge_system(int e) const {
  G14EdgeSystem s;
  s.M = edge_equations(t_, b_, gluing_[e], e, s.columns);
  const int n = b_.size(), m = b_.last();
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

NotSeparable G14LocalProblems::not_separable(int v, int e, double residual) const {
  return NotSeparable(e, v,
                      "the corner data at vertex " + std::to_string(v) + " cannot be lifted along the edge " +
                          std::to_string(t_.edge(e).g0) + "-" + std::to_string(t_.edge(e).g1) + " (residual " +
                          std::to_string(residual) + ")");
}

Eigen::MatrixXd G14LocalProblems::corner_data(int v, std::vector<int>& vc) const {
  const int fs = b_.face_size();
  vc.clear();
  for (const auto& [f, c] : t_.vertex_corners(v))
    for (int i : corner_block(b_, c)) vc.push_back(f * fs + i);
  std::map<int, int> pos;
  for (std::size_t i = 0; i < vc.size(); ++i) pos[vc[i]] = static_cast<int>(i);
  std::vector<Eigen::RowVectorXd> eqs;
  for (int e : t_.vertex_edges(v)) {
    if (t_.edge(e).boundary()) continue;
    std::vector<int> cols;
    const Eigen::MatrixXd M = vertex_equations(t_, b_, gluing_[e], e, t_.edge(e).g0 == v ? 0 : 1, cols);
    for (int rr = 0; rr < M.rows(); ++rr) {
      Eigen::RowVectorXd row = Eigen::RowVectorXd::Zero(static_cast<Eigen::Index>(vc.size()));
      for (std::size_t c = 0; c < cols.size(); ++c) row(pos.at(cols[c])) += M(rr, c);
      eqs.push_back(row);
    }
  }
  Eigen::MatrixXd E(static_cast<Eigen::Index>(eqs.size()), static_cast<Eigen::Index>(vc.size()));
  for (std::size_t rr = 0; rr < eqs.size(); ++rr) E.row(rr) = eqs[rr];
  return numerical_nullspace(E);
}

Eigen::VectorXd G14LocalProblems::lift_along(int v, int e, const G14EdgeSystem& s, const Eigen::MatrixXd& H, int h,
                                             const std::map<int, int>& pos) const {
  const int end = t_.edge(e).g0 == v ? 0 : 1;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(s.M.rows());
  for (int p : s.end_corner[end]) rhs -= s.M.col(p) * H(pos.at(s.columns[p]), h);
  Eigen::VectorXd x = s.solver.solve(rhs);
  const double residual = (s.M_strip * x - rhs).norm();
  if (residual > 1e-9 * std::max(1.0, rhs.norm())) throw not_separable(v, e, residual);
  return x;
}

std::vector<BrokenFunction> G14LocalProblems::lifted(int v, const std::vector<int>& vc, const Eigen::MatrixXd& H,
                                                     const SystemOf& system) const {
  std::map<int, int> pos;
  for (std::size_t i = 0; i < vc.size(); ++i) pos[vc[i]] = static_cast<int>(i);
  std::vector<BrokenFunction> out;
  for (int h = 0; h < H.cols(); ++h) {
    BrokenFunction fn;
    for (std::size_t i = 0; i < vc.size(); ++i) fn[vc[i]] += H(i, h);
    for (int e : t_.vertex_edges(v)) {
      if (t_.edge(e).boundary()) continue;
      const G14EdgeSystem& s = system(e);
      const Eigen::VectorXd x = lift_along(v, e, s, H, h, pos);
      for (std::size_t c = 0; c < s.strip.size(); ++c) fn[s.columns[s.strip[c]]] += x(c);
    }
    out.push_back(std::move(fn));
  }
  return out;
}

std::vector<BrokenFunction> G14LocalProblems::vertex_functions(int v, const SystemOf& system) const {
  std::vector<int> vc;
  const Eigen::MatrixXd H = corner_data(v, vc);
  const std::vector<BrokenFunction> lifts = lifted(v, vc, H, system);
  // Orthonormalize the lifted functions (same span): near a vertex whose gluing value is small
  // but not zero, twist data force second tangential derivatives ~ 1/A along the edge, and the
  // raw lifts would be badly scaled and nearly dependent.
  std::map<int, int> rows;
  for (const auto& fn : lifts)
    for (const auto& [i, x] : fn) rows.emplace(i, 0);
  int r = 0;
  for (auto& [i, p] : rows) p = r++;
  Eigen::MatrixXd L = Eigen::MatrixXd::Zero(r, static_cast<Eigen::Index>(lifts.size()));
  for (std::size_t c = 0; c < lifts.size(); ++c)
    for (const auto& [i, x] : lifts[c]) L(rows.at(i), c) = x;
  const Eigen::MatrixXd Q = Eigen::JacobiSVD<Eigen::MatrixXd>(L, Eigen::ComputeThinU).matrixU();
  std::vector<BrokenFunction> out;
  for (int c = 0; c < Q.cols(); ++c) {
    BrokenFunction fn;
    for (const auto& [i, p] : rows) fn[i] = Q(p, c);
    out.push_back(std::move(fn));
  }
  return out;
}

std::vector<BrokenFunction> G14LocalProblems::edge_functions(int e, const G14EdgeSystem* s) const {
  std::vector<BrokenFunction> out;
  const QuadEdge& edge = t_.edge(e);
  const int fs = b_.face_size(), m = b_.last();
  if (edge.boundary()) {
    const QuadSide side = edge.sides[0];
    for (int rr = 0; rr < 2; ++rr) {
      const std::vector<int> row = side_row(b_, side.local_edge, rr);
      for (int i = 2; i <= m - 2; ++i) out.push_back({{side.face * fs + row[i], 1.0}});
    }
    return out;
  }
  const Eigen::MatrixXd N = numerical_nullspace(s->M_strip);
  for (int c = 0; c < N.cols(); ++c) {
    BrokenFunction fn;
    for (std::size_t i = 0; i < s->strip.size(); ++i) fn[s->columns[s->strip[i]]] += N(i, c);
    out.push_back(std::move(fn));
  }
  return out;
}

std::vector<BrokenFunction> G14LocalProblems::face_functions(int f) const {
  const int fs = b_.face_size();
  std::vector<BrokenFunction> out;
  for (int i : interior_indices(b_)) out.push_back({{f * fs + i, 1.0}});
  return out;
}

int G14LocalProblems::face_count() const { return static_cast<int>(interior_indices(b_).size()); }

G14Numbering G14LocalProblems::count_functions() const {
  G14Numbering n;
  n.vertex_first.assign(t_.num_vertices() + 1, 0);
  std::vector<int> edge_counts(t_.num_edges(), -1);
  std::map<int, G14EdgeSystem> systems;  // of one vertex's interior edges
  const SystemOf system = [&](int e) -> const G14EdgeSystem& { return systems.at(e); };
  // Vertex by vertex as the whole basis lifts them, so the first datum that does not lift is the
  // one the whole basis reports.
  for (int v = 0; v < t_.num_vertices(); ++v) {
    systems.clear();
    for (int e : t_.vertex_edges(v))
      if (!t_.edge(e).boundary()) systems.emplace(e, edge_system(e));
    const int count = t_.vertex_corners(v).empty() ? 0 : static_cast<int>(vertex_functions(v, system).size());
    n.vertex_first[v + 1] = n.vertex_first[v] + count;
    for (const auto& [e, s] : systems)
      if (t_.edge(e).g0 == v) edge_counts[e] = static_cast<int>(edge_functions(e, &s).size());
  }
  n.edge_first.assign(t_.num_edges() + 1, n.vertex_first.back());
  for (int e = 0; e < t_.num_edges(); ++e) {
    const int count = t_.edge(e).boundary() ? static_cast<int>(edge_functions(e, nullptr).size()) : edge_counts[e];
    n.edge_first[e + 1] = n.edge_first[e] + count;
  }
  n.per_face = face_count();
  return n;
}

}  // namespace iga
