#include "spaces/g1/g1_basis.hpp"
#include "config/worth_threads.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <numeric>
#include <string>

#include "spaces/g1/bernstein_face.hpp"
#include "spaces/g1/g1_local_problems.hpp"

namespace iga {

namespace {

// Relative rank threshold of the local null spaces, on singular values (edges) or QR pivots
// (vertices); the Bernstein rows are O(1).
constexpr double kRankTolerance = 1e-10;

/// Unknown set: (face, index) pairs, deduplicated, with a lookup. The local sets have at most a
/// few dozen entries, so a linear scan beats building a hash map for every edge and vertex.
struct Unknowns {
  std::vector<std::pair<int, int>> list;
  explicit Unknowns(int /*k*/) {}
  void add(const std::vector<std::pair<int, int>>& items) {
    for (const auto& [f, i] : items)
      if (find(f, i) < 0) list.push_back({f, i});
  }
  int find(int f, int i) const {
    for (size_t c = 0; c < list.size(); ++c)
      if (list[c].first == f && list[c].second == i) return static_cast<int>(c);
    return -1;
  }
  int size() const { return static_cast<int>(list.size()); }
};

/// Rows restricted to the unknowns (coefficients outside are zero).
Eigen::MatrixXd restrict_rows(const std::vector<std::vector<FaceCoefficient>>& rows, const Unknowns& u) {
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(rows.size()), u.size());
  for (size_t r = 0; r < rows.size(); ++r)
    for (const FaceCoefficient& c : rows[r]) {
      const int col = u.find(c.face, c.index);
      if (col >= 0) m(static_cast<Eigen::Index>(r), col) += c.value;
    }
  return m;
}

/// Orthonormal basis of the null space of m (n columns), n x nullity: the trailing columns of Q in
/// a column-pivoted QR of mᵀ (its leading `rank` columns span the row space of m). Several times
/// cheaper than an SVD at the vertex problems' sizes (a few dozen rows and columns); the rows are
/// O(1)-scaled, so the pivots reveal the rank as the singular values would.
Eigen::MatrixXd null_space(const Eigen::MatrixXd& m, int n) {
  if (m.rows() == 0) return Eigen::MatrixXd::Identity(n, n);
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(m.transpose());
  qr.setThreshold(kRankTolerance);
  const Eigen::MatrixXd q = qr.householderQ() * Eigen::MatrixXd::Identity(n, n);
  return q.rightCols(n - qr.rank());
}

/// Orthonormal bases of ker(a) and of its orthogonal complement in R^r (r = a.cols()).
void split_kernel(const Eigen::MatrixXd& a, Eigen::MatrixXd& kernel, Eigen::MatrixXd& complement) {
  const Eigen::Index r = a.cols();
  if (a.rows() == 0 || r == 0) {
    kernel = Eigen::MatrixXd::Identity(r, r);
    complement.resize(r, 0);
    return;
  }
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(a, Eigen::ComputeFullV);
  const Eigen::VectorXd& s = svd.singularValues();
  Eigen::Index rank = 0;
  for (Eigen::Index i = 0; i < s.size(); ++i)
    if (s[i] > 1e-10 * std::max(s[0], 1e-300)) ++rank;
  complement = svd.matrixV().leftCols(rank);
  kernel = svd.matrixV().rightCols(r - rank);
}

/// Orthonormal basis of the complement of unit vector direction y in R^rho (rho x (rho-1)).
Eigen::MatrixXd complement_of(const Eigen::VectorXd& y) {
  Eigen::HouseholderQR<Eigen::MatrixXd> qr(Eigen::MatrixXd(y.normalized()));
  const Eigen::MatrixXd q = qr.householderQ() * Eigen::MatrixXd::Identity(y.size(), y.size());
  return q.rightCols(y.size() - 1);
}

/// Coordinates (in the corner-data range basis `ur`, r columns) of the r vertex functions' corner
/// data: column 0 is the constant (o = urᵀ·ones). At a boundary vertex the rest are chosen so that
/// the functions with a nonzero trace have independent traces (columns 1..ρ-1), then zero-trace
/// functions with independent next-row data, then functions vanishing to first order on the
/// boundary: the boundary projections for Dirichlet and clamped data are then nonsingular.
Eigen::MatrixXd vertex_targets(const Eigen::MatrixXd& ur, const Eigen::VectorXd& o, const std::vector<int>& trace_rows,
                               const std::vector<int>& normal_rows) {
  const Eigen::Index r = ur.cols();
  Eigen::MatrixXd out(r, r);
  out.col(0) = o;
  if (trace_rows.empty()) {
    out.rightCols(r - 1) = complement_of(o);
    return out;
  }
  auto rows_of = [&](const std::vector<int>& idx, const Eigen::MatrixXd& basis) {
    Eigen::MatrixXd m(static_cast<Eigen::Index>(idx.size()), basis.cols());
    for (size_t i = 0; i < idx.size(); ++i) m.row(static_cast<Eigen::Index>(i)) = ur.row(idx[i]) * basis;
    return m;
  };
  Eigen::MatrixXd k1, c1, k2, c2;
  split_kernel(rows_of(trace_rows, Eigen::MatrixXd::Identity(r, r)), k1, c1);
  Eigen::Index col = 1;
  if (c1.cols() > 1) {
    const Eigen::MatrixXd rest = c1 * complement_of(c1.transpose() * o);
    out.middleCols(col, rest.cols()) = rest;
    col += rest.cols();
  }
  split_kernel(rows_of(normal_rows, k1), k2, c2);
  out.middleCols(col, c2.cols()) = k1 * c2;
  col += c2.cols();
  out.middleCols(col, k2.cols()) = k1 * k2;
  return out;
}

void solve_edge_local(const PatchMesh& mesh, int e, const std::vector<std::vector<FaceCoefficient>>& rows, int k,
                      EdgeLocal& l) {
  Unknowns u(k);
  u.add(l.unknowns);
  const Eigen::MatrixXd m = restrict_rows(rows, u);
  if (m.rows() == 0 || m.cols() == 0)  // the rank test below reads the largest singular value
    throw IncompleteBasis("edge " + std::to_string(e) + " has no edge coefficients at degree " + std::to_string(k));
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(m, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::VectorXd& s = svd.singularValues();
  Eigen::Index rank = 0;
  for (Eigen::Index i = 0; i < s.size(); ++i)
    if (s[i] > kRankTolerance * s[0]) ++rank;
  l.null = svd.matrixV().rightCols(m.cols() - rank);
  l.range = svd.matrixV().leftCols(rank);
  const Eigen::MatrixXd coker = svd.matrixU().rightCols(m.rows() - rank);
  const MeshEdge& me = mesh.edge(e);
  const int f1 = me.first.face, f2 = me.second.face;
  const int n1 = mesh.num_corners(f1), n2 = mesh.num_corners(f2);
  for (int end = 0; end < 2; ++end) {
    // `first` runs X -> Y along its local edge e1 (corner e1 at X), `second` Y -> X (corner e2 at Y).
    const int c1 = (me.first.local_edge + end) % n1, c2 = (me.second.local_edge + 1 - end) % n2;
    EdgeLocal::End& d = l.end[end];
    for (int idx : corner_coefficients(mesh.shape(f1), k, c1)) d.corners.push_back({f1, idx});
    for (int idx : corner_coefficients(mesh.shape(f2), k, c2)) d.corners.push_back({f2, idx});
    Unknowns cu(k);
    cu.add(d.corners);
    const Eigen::MatrixXd a = restrict_rows(rows, cu);
    d.compat = coker.transpose() * a;
    d.scaled = s.head(rank).cwiseInverse().asDiagonal() * (svd.matrixU().leftCols(rank).transpose() * a);
  }
}

}  // namespace

std::vector<FaceCoefficient> to_function(const Eigen::VectorXd& x, const std::vector<std::pair<int, int>>& u,
                                         bool normalize) {
  const double scale = normalize ? x.cwiseAbs().maxCoeff() : 1.0;
  std::vector<FaceCoefficient> f;
  for (size_t i = 0; i < u.size(); ++i)
    if (x[static_cast<Eigen::Index>(i)] != 0.0) f.push_back({u[i].first, u[i].second, x[static_cast<Eigen::Index>(i)] / scale});
  return f;
}

std::vector<std::vector<FaceCoefficient>> edge_functions(const PatchMesh& mesh, int e, const EdgeLocal& l) {
  std::vector<std::vector<FaceCoefficient>> out;
  if (mesh.edge(e).boundary()) {
    for (const auto& [f, i] : l.unknowns) out.push_back({{f, i, 1.0}});
  } else {
    for (Eigen::Index j = 0; j < l.null.cols(); ++j) out.push_back(to_function(l.null.col(j), l.unknowns, true));
  }
  return out;
}

std::vector<std::vector<FaceCoefficient>> face_functions(const PatchMesh& mesh, int f, int k) {
  std::vector<std::vector<FaceCoefficient>> out;
  for (int i : interior_coefficients(mesh.shape(f), k)) out.push_back({{f, i, 1.0}});
  return out;
}

FaceExtractionAssembly::FaceExtractionAssembly(std::vector<int> faces)
    : faces_(std::move(faces)), dofs_(faces_.size()), triplets_(faces_.size()) {}

void FaceExtractionAssembly::add(int g, const std::vector<FaceCoefficient>& function) {
  for (const FaceCoefficient& c : function) {
    const auto it = std::lower_bound(faces_.begin(), faces_.end(), c.face);
    if (it == faces_.end() || *it != c.face) continue;
    const size_t s = static_cast<size_t>(it - faces_.begin());
    std::vector<int>& dofs = dofs_[s];
    if (dofs.empty() || dofs.back() != g) dofs.push_back(g);
    triplets_[s].push_back({c.index, static_cast<int>(dofs.size()) - 1, c.value});
  }
}

void FaceExtractionAssembly::finish(const PatchMesh& mesh, int k, G1Basis& basis) {
  basis.extraction.resize(faces_.size());
  for (size_t s = 0; s < faces_.size(); ++s) {
    basis.extraction[s].resize(bernstein_count(mesh.shape(faces_[s]), k), static_cast<Eigen::Index>(dofs_[s].size()));
    basis.extraction[s].setFromTriplets(triplets_[s].begin(), triplets_[s].end());
  }
  basis.face_dofs = std::move(dofs_);
}

int vertex_function_count(const PatchMesh& mesh, const std::vector<EdgeGluing>& gluing, int v) {
  const VertexFan& fan = mesh.fan(v);
  int crossing = 0;
  for (int e : fan.edge) crossing += crossing_at(mesh, gluing, e, v) ? 1 : 0;
  const int faces = static_cast<int>(fan.face.size());
  const bool crossing_vertex = !fan.boundary && fan.valence() == 4 && crossing == 4;
  return 3 + faces - crossing + (crossing_vertex ? 1 : 0);
}

int theorem_dimension(const PatchMesh& mesh, const std::vector<EdgeGluing>& gluing, int k) {
  int sum_d = 0, crossing_vertices = 0, used_vertices = 0;
  for (int e = 0; e < mesh.num_edges(); ++e) {
    const MeshEdge& me = mesh.edge(e);
    // Boundary edges count as d = 2k + 3 − F_Δ(σ) (Remark 4.14).
    const bool triangle = mesh.shape(me.first.face) == CellShape::triangle;
    sum_d += me.boundary() ? 2 * k + 3 - (triangle ? 1 : 0) : syzygy_dimension(gluing[e], k);
  }
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    const VertexFan& fan = mesh.fan(v);
    if (fan.face.empty()) continue;
    ++used_vertices;
    if (fan.boundary || fan.valence() != 4) continue;
    bool all = true;
    for (int e : fan.edge) all = all && crossing_at(mesh, gluing, e, v);
    crossing_vertices += all ? 1 : 0;
  }
  int quads = 0, triangles = 0;
  for (int f = 0; f < mesh.num_faces(); ++f) (mesh.shape(f) == CellShape::triangle ? triangles : quads) += 1;
  return (k - 3) * (k - 3) * quads + (k - 5) * (k - 4) / 2 * triangles + sum_d + 4 * quads + 3 * triangles -
         9 * mesh.num_edges() + 3 * used_vertices + crossing_vertices;
}

/// The vertex functions of vertex v (notes §4.5), value function first. The local problem has the
/// unknowns C (corner sets of v, 4 per face) and R_τ (each edge τ at v: rows 0–1 along τ minus the
/// corner sets, the edge problem's unknowns); the rows of an interior edge τ at v are
/// A_τ x_C + E_τ x_R_τ = 0 (coefficients with index >= 2 along τ meet no other edge's rows at v).
/// So the corner data the local null space reaches are H = {x_C : coker_τᵀ A_τ x_C = 0 for every
/// τ}, and the minimum-norm local function with corner data h ∈ H is x_R_τ = −E_τ⁺ A_τ h (0 on
/// boundary edges). This is the null space of all rows on C ∪ R, reduced to its part orthogonal
/// to the edge functions, without the large dense SVD of the whole local system: one SVD of a
/// (Σ dim coker) x 4F matrix per vertex, the edge parts reused from the edge problems.
std::vector<std::vector<FaceCoefficient>> build_vertex_functions(const PatchMesh& mesh,
                                                                 const std::vector<EdgeGluing>& gluing, int k, int v,
                                                                 const std::vector<const EdgeLocal*>& at,
                                                                 const std::string& where) {
  const VertexFan& fan = mesh.fan(v);
  const int nf = static_cast<int>(fan.face.size());
  Unknowns corners(k);
  for (int i = 0; i < nf; ++i) {
    std::vector<std::pair<int, int>> c;
    for (int idx : corner_coefficients(mesh.shape(fan.face[i]), k, fan.corner[i])) c.push_back({fan.face[i], idx});
    corners.add(c);
  }
  const int nc = corners.size();
  // The interior edges at v, their data at this end and its columns in the corner data.
  std::vector<const EdgeLocal::End*> ends;
  std::vector<const EdgeLocal*> edges;
  std::vector<std::array<int, 8>> columns;
  Eigen::Index compat_rows = 0;
  for (size_t t = 0; t < fan.edge.size(); ++t)
    if (const int e = fan.edge[t]; !mesh.edge(e).boundary()) {
      const EdgeLocal::End& d = at[t]->end[mesh.edge(e).x == v ? 0 : 1];
      std::array<int, 8> col;
      for (int j = 0; j < 8; ++j) {
        col[j] = corners.find(d.corners[j].first, d.corners[j].second);
        if (col[j] < 0) throw std::logic_error("G1 basis: edge corner set outside the vertex fan");
      }
      ends.push_back(&d);
      edges.push_back(at[t]);
      columns.push_back(col);
      compat_rows += d.compat.rows();
    }
  Eigen::MatrixXd compat = Eigen::MatrixXd::Zero(compat_rows, nc);
  Eigen::Index r0 = 0;
  for (size_t i = 0; i < ends.size(); ++i) {
    for (int j = 0; j < 8; ++j) compat.block(r0, columns[i][j], ends[i]->compat.rows(), 1) += ends[i]->compat.col(j);
    r0 += ends[i]->compat.rows();
  }
  const Eigen::MatrixXd ur = null_space(compat, nc);  // orthonormal basis of H
  const int rank = static_cast<int>(ur.cols());
  const int expected = vertex_function_count(mesh, gluing, v);
  if (rank != expected)
    throw IncompleteBasis(where + "vertex " + std::to_string(v) + " has " + std::to_string(rank) +
                          " independent corner data; expected " + std::to_string(expected));
  const Eigen::VectorXd ones = Eigen::VectorXd::Ones(nc);
  if ((ur * (ur.transpose() * ones) - ones).norm() > 1e-8 * ones.norm())
    throw IncompleteBasis(where + "vertex " + std::to_string(v) + ": constants are not locally representable");
  // Minimum-norm local function with corner data h ∈ H (projected onto H against round-off).
  std::vector<std::pair<int, int>> list = corners.list;  // C, then R_τ of each interior edge
  for (const EdgeLocal* l : edges) list.insert(list.end(), l->unknowns.begin(), l->unknowns.end());
  auto function = [&](const Eigen::VectorXd& h, bool normalize) {
    Eigen::VectorXd x(static_cast<Eigen::Index>(list.size()));
    x.head(nc) = ur * (ur.transpose() * h);
    Eigen::Index n = nc;
    for (size_t i = 0; i < ends.size(); ++i) {
      Eigen::Matrix<double, 8, 1> xe;
      for (int j = 0; j < 8; ++j) xe[j] = x[columns[i][j]];
      const Eigen::VectorXd y = ends[i]->scaled * xe;
      x.segment(n, edges[i]->range.rows()) = -(edges[i]->range * y);
      n += edges[i]->range.rows();
    }
    return to_function(x, list, normalize);
  };
  // Positions in the corner data of the trace (row 0) and next-row (row 1) coefficients along
  // the boundary edges at a boundary vertex.
  std::vector<int> trace_rows, normal_rows;
  if (fan.boundary) {
    const int f0 = fan.face.front(), c0 = fan.corner.front();
    const int fl = fan.face.back(), cl = fan.corner.back();
    const CellShape s0 = mesh.shape(f0), sl = mesh.shape(fl);
    const int before = cl + mesh.num_corners(fl) - 1;  // the last face's edge ending at v
    for (int m = 0; m <= 1; ++m) {
      trace_rows.push_back(corners.find(f0, edge_coefficient(s0, k, c0, m, 0)));
      normal_rows.push_back(corners.find(f0, edge_coefficient(s0, k, c0, m, 1)));
      trace_rows.push_back(corners.find(fl, edge_coefficient(sl, k, before, edge_row_last(sl, k, 0) - m, 0)));
      normal_rows.push_back(corners.find(fl, edge_coefficient(sl, k, before, edge_row_last(sl, k, 1) - m, 1)));
    }
  }
  const Eigen::MatrixXd targets = vertex_targets(ur, ur.transpose() * ones, trace_rows, normal_rows);
  std::vector<std::vector<FaceCoefficient>> out;
  out.push_back(function(ones, false));
  for (int j = 1; j < rank; ++j) out.push_back(function(ur * targets.col(j), true));
  return out;
}

void check_g1_degree(const PatchMesh& mesh, int k) {
  if (k < 3) throw IncompleteBasis("G1 basis needs degree >= 3");
  // Below 4 the corner sets of a triangle overlap (λ0 λ1 λ2 belongs to all three).
  if (k < 4 && mesh.has_triangles()) throw IncompleteBasis("G1 basis on triangles needs degree >= 4");
  // Below 4 the 2x2 corner sets of a quadrilateral fill its first two rows along every edge: no
  // coefficient is left for the edge functions, so the local construction cannot be complete.
  if (k < 4 && mesh.num_faces() > 0)
    throw IncompleteBasis("G1 basis on quadrilaterals needs degree >= 4 (at degree " + std::to_string(k) +
                          " the corner coefficients leave no edge coefficients)");
}

std::string solve_g1_edge(const PatchMesh& mesh, const std::vector<EdgeGluing>& gluing,
                          const EdgeCollocation& collocation, int k, int e, const std::string& where, EdgeLocal& l) {
  const MeshEdge& me = mesh.edge(e);
  add_edge_rows(mesh, k, me.first.face, me.first.local_edge, 2, 2, l.unknowns);
  if (me.boundary()) return {};
  add_edge_rows(mesh, k, me.second.face, me.second.local_edge, 2, 2, l.unknowns);
  try {
    solve_edge_local(mesh, e, edge_constraint_rows(mesh, gluing[e], collocation), k, l);
  } catch (const IncompleteBasis& ex) {
    return where + ex.what();
  }
  const int expected = syzygy_dimension(gluing[e], k) - 9 + (gluing[e].crossing_x ? 1 : 0) + (gluing[e].crossing_y ? 1 : 0);
  if (l.null.cols() != expected)
    return where + "edge " + std::to_string(e) + " has " + std::to_string(l.null.cols()) +
           " local functions, expected " + std::to_string(expected);
  return {};
}

G1Basis build_g1_basis(const PatchMesh& mesh, const std::vector<EdgeGluing>& gluing, int k) {
  check_g1_degree(mesh, k);
  G1Basis basis;
  basis.degree = k;
  std::vector<int> all_faces(mesh.num_faces());
  std::iota(all_faces.begin(), all_faces.end(), 0);
  FaceExtractionAssembly extraction(std::move(all_faces));
  auto add = [&](const std::vector<FaceCoefficient>& f, G1FunctionInfo info) {
    extraction.add(basis.dimension(), f);
    basis.info.push_back(info);
  };
  const std::string where = where_of(mesh, k);

  // Per interior edge: its rows (the Bernstein jets at the collocation points computed once), its
  // edge functions and what the vertex problems reuse (EdgeLocal). Independent per edge: parallel,
  // results by index.
  const EdgeCollocation collocation(k);
  std::vector<EdgeLocal> local(mesh.num_edges());
  FirstError edge_error;
#pragma omp parallel for schedule(dynamic, 16) if (worth_threads(mesh.num_edges()))
  for (int e = 0; e < mesh.num_edges(); ++e)
    if (const std::string error = solve_g1_edge(mesh, gluing, collocation, k, e, where, local[e]); !error.empty())
      edge_error.offer(e, error);
  edge_error.throw_if_any();
  for (int e = 0; e < mesh.num_edges(); ++e)
    for (const std::vector<FaceCoefficient>& f : edge_functions(mesh, e, local[e])) add(f, {G1Entity::edge, e});

  // Vertex functions: per vertex a list of functions, built in parallel, appended in vertex order
  // (the basis does not depend on the number of threads).
  std::vector<std::vector<std::vector<FaceCoefficient>>> vertex_functions(mesh.num_vertices());
  FirstError vertex_error;
#pragma omp parallel for schedule(dynamic, 16) if (worth_threads(mesh.num_vertices()))
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    if (mesh.fan(v).face.empty()) continue;
    try {
      std::vector<const EdgeLocal*> at;
      for (int e : mesh.fan(v).edge) at.push_back(&local[e]);
      vertex_functions[v] = build_vertex_functions(mesh, gluing, k, v, at, where);
    } catch (const IncompleteBasis& ex) {
      vertex_error.offer(v, ex.what());
    }
  }
  vertex_error.throw_if_any();
  for (int v = 0; v < mesh.num_vertices(); ++v)
    for (size_t j = 0; j < vertex_functions[v].size(); ++j) add(vertex_functions[v][j], {G1Entity::vertex, v, j == 0});

  for (int f = 0; f < mesh.num_faces(); ++f)
    for (const std::vector<FaceCoefficient>& fn : face_functions(mesh, f, k)) add(fn, {G1Entity::face, f});
  extraction.finish(mesh, k, basis);
  return basis;
}

}  // namespace iga
