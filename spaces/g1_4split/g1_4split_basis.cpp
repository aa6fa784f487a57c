#include "spaces/g1_4split/g1_4split_basis.hpp"

#include <Eigen/Dense>
#include <Eigen/SVD>
#include <algorithm>
#include <numeric>
#include <cmath>
#include <map>

#include "spaces/g1_4split/edge_equations.hpp"
#include "spaces/g1_4split/g14_local_problems.hpp"
#include "spaces/g1_4split/line_gluing.hpp"

namespace iga {

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
  const int fs = b.face_size();
  const G14LocalProblems local(t, gluing, b);
  std::vector<Eigen::Triplet<double>> trip;
  int col = 0;
  auto add = [&](const std::vector<BrokenFunction>& functions) {
    for (const BrokenFunction& fn : functions) {
      for (const auto& [i, x] : kept_entries(fn)) trip.emplace_back(i, col, x);
      ++col;
    }
  };
  G14Numbering& n = basis.numbering;

  std::vector<G14EdgeSystem> systems(t.num_edges());
  for (int e = 0; e < t.num_edges(); ++e)
    if (!t.edge(e).boundary()) systems[e] = local.edge_system(e);
  const G14LocalProblems::SystemOf system = [&](int e) -> const G14EdgeSystem& { return systems[e]; };

  // Vertex functions: a basis of the admissible corner data, lifted along every interior edge.
  n.vertex_first.assign(t.num_vertices() + 1, 0);
  for (int v = 0; v < t.num_vertices(); ++v) {
    add(local.vertex_functions(v, system));
    n.vertex_first[v + 1] = col;
  }

  // Edge functions: strip solutions with zero corner data.
  n.edge_first.assign(t.num_edges() + 1, col);
  for (int e = 0; e < t.num_edges(); ++e) {
    add(local.edge_functions(e, t.edge(e).boundary() ? nullptr : &systems[e]));
    n.edge_first[e + 1] = col;
  }

  // Face functions.
  n.per_face = local.face_count();
  for (int f = 0; f < t.num_faces(); ++f) add(local.face_functions(f));

  basis.functions.resize(t.num_faces() * fs, col);
  basis.functions.setFromTriplets(trip.begin(), trip.end());

  // Per-face extraction over the face's functions by entity (G14Numbering::face_functions: what
  // a skeleton numbers without solving).
  std::vector<int> every(t.num_faces());
  std::iota(every.begin(), every.end(), 0);
  std::vector<std::vector<int>> face_dofs(t.num_faces());
  for (int f = 0; f < t.num_faces(); ++f) n.face_functions(t, f, face_dofs[f]);
  G14FaceExtractions extractions(fs, every, std::move(face_dofs));
  for (int c = 0; c < basis.functions.outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(basis.functions, c); it; ++it)
      extractions.add(c, static_cast<int>(it.row()), it.value());
  basis.extraction = extractions.finish();
  basis.face_dofs = extractions.face_functions();
  return basis;
}

}  // namespace iga
