#include "spaces/g1/gluing_data.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <stdexcept>
#include <string>

namespace iga {

namespace {

double det2(const Point2& p, const Point2& q) { return p.x() * q.y() - p.y() * q.x(); }

Eigen::Vector3d quadratic_through(double v0, double vh, double v1) {
  const double p2 = 2.0 * (v0 + v1 - 2.0 * vh);
  return {v0, v1 - v0 - p2, p2};
}

/// Physical tangent e and cross directions w1, w2 at parameter t.
void physical_vectors(const PatchMesh& mesh, const EdgeFrame& fr, double t, Point2& e, Point2& e2, Point2& w1,
                      Point2& w2) {
  const Eigen::Matrix2d j1 = mesh.map(fr.face1, fr.start1 + t * fr.tangent1).jacobian;
  const Eigen::Matrix2d j2 = mesh.map(fr.face2, fr.start2 + t * fr.tangent2).jacobian;
  e = j1 * fr.tangent1;
  e2 = j2 * fr.tangent2;
  w1 = j1 * fr.cross1;
  w2 = j2 * fr.cross2;
}

}  // namespace

double eval_poly(const Eigen::Vector3d& p, double t) { return p[0] + t * (p[1] + t * p[2]); }

EdgeFrame edge_frame(const PatchMesh& mesh, int edge) {
  const MeshEdge& me = mesh.edge(edge);
  EdgeFrame fr;
  fr.face1 = me.first.face;
  const int e1 = me.first.local_edge;
  const CellShape s1 = mesh.shape(fr.face1);
  fr.start1 = reference_corner(s1, e1);
  fr.tangent1 = reference_corner(s1, e1 + 1) - fr.start1;
  fr.cross1 = reference_corner(s1, e1 - 1) - fr.start1;
  if (!me.boundary()) {
    fr.face2 = me.second.face;
    const int e2 = me.second.local_edge;  // runs Y -> X on the second face
    const CellShape s2 = mesh.shape(fr.face2);
    fr.start2 = reference_corner(s2, e2 + 1);
    fr.tangent2 = reference_corner(s2, e2) - fr.start2;
    fr.cross2 = reference_corner(s2, e2 + 2) - fr.start2;
  }
  return fr;
}

namespace {

/// Whether the cross edges of the two faces at the far end Y (towards their other neighbours of
/// Y) are collinear: the edge is crossing at Y (notes §1.7, computed from the geometry).
bool crossing_at_far_end(const PatchMesh& mesh, int edge) {
  const MeshEdge& me = mesh.edge(edge);
  const int f1 = me.first.face, f2 = me.second.face;
  const CellShape s1 = mesh.shape(f1), s2 = mesh.shape(f2);
  const int e1 = me.first.local_edge, e2 = me.second.local_edge;
  const Point2 y1 = reference_corner(s1, e1 + 1), y2 = reference_corner(s2, e2);
  const Point2 w1 = mesh.map(f1, y1).jacobian * (reference_corner(s1, e1 + 2) - y1);
  const Point2 w2 = mesh.map(f2, y2).jacobian * (reference_corner(s2, e2 - 1) - y2);
  return std::abs(det2(w1, w2)) <= 1e-10 * w1.norm() * w2.norm();
}

}  // namespace

std::vector<EdgeGluing> gluing_from_geometry(const PatchMesh& mesh) {
  std::vector<EdgeGluing> out(mesh.num_edges());
  for (int id = 0; id < mesh.num_edges(); ++id) {
    if (mesh.edge(id).boundary()) continue;
    const EdgeFrame fr = edge_frame(mesh, id);
    const double ts[3] = {0.0, 0.5, 1.0};
    double av[3], bv[3], cv[3];
    double wnorm[3] = {0.0, 0.0, 0.0};
    const std::string where = mesh.name() + ": edge " + std::to_string(id) + " (patches " +
                              std::to_string(fr.face1) + ", " + std::to_string(fr.face2) + ")";
    for (int s = 0; s < 3; ++s) {
      Point2 e, e2, w1, w2;
      physical_vectors(mesh, fr, ts[s], e, e2, w1, w2);
      if ((e - e2).norm() > 1e-12 * e.norm())
        throw std::logic_error(where + ": the two patches parametrise the edge differently");
      cv[s] = det2(e, w2);
      av[s] = det2(w1, w2);
      bv[s] = det2(e, w1);
      wnorm[s] = w1.norm() * w2.norm();
    }
    EdgeGluing g;
    g.edge = id;
    g.a = quadratic_through(av[0], av[1], av[2]);
    g.b = quadratic_through(bv[0], bv[1], bv[2]);
    g.c = quadratic_through(cv[0], cv[1], cv[2]);
    g.triangle1 = mesh.shape(fr.face1) == CellShape::triangle;
    g.triangle2 = mesh.shape(fr.face2) == CellShape::triangle;
    g.crossing_x = std::abs(av[0]) <= 1e-10 * wnorm[0];
    g.crossing_y = crossing_at_far_end(mesh, id);
    const double scale = std::max(std::abs(cv[0]), std::abs(cv[2]));
    g.a /= scale;
    g.b /= scale;
    g.c /= scale;
    // Exact checks at points other than the interpolation nodes.
    for (double t : {0.1, 0.37, 0.8, 0.93}) {
      Point2 e, e2, w1, w2;
      physical_vectors(mesh, fr, t, e, e2, w1, w2);
      const Point2 r = eval_poly(g.c, t) * w1 - eval_poly(g.a, t) * e - eval_poly(g.b, t) * w2;
      if (r.norm() > 1e-11 * w1.norm() * std::max(1.0, std::abs(eval_poly(g.c, t))) * 10)
        throw std::logic_error(where + ": c w1 = a e + b w2 fails at t = " + std::to_string(t));
      if (!(eval_poly(g.b, t) * eval_poly(g.c, t) < 0.0))
        throw std::logic_error(where + ": b/c must be negative along the edge (faces overlap)");
    }
    for (double t : {0.0, 1.0})
      if (!(eval_poly(g.b, t) * eval_poly(g.c, t) < 0.0))
        throw std::logic_error(where + ": b/c must be negative along the edge (faces overlap)");
    out[id] = g;
  }
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    if (mesh.fan(v).face.empty() || mesh.fan(v).boundary) continue;
    const Eigen::Matrix2d p = vertex_jet_product(mesh, out, v);
    if ((p - Eigen::Matrix2d::Identity()).cwiseAbs().maxCoeff() > 1e-9)
      throw std::logic_error(mesh.name() + ": Condition 2.6 fails at interior vertex " + std::to_string(v));
  }
  return out;
}

Eigen::Matrix2d vertex_jet_product(const PatchMesh& mesh, const std::vector<EdgeGluing>& gluing, int v) {
  const VertexFan& fan = mesh.fan(v);
  Eigen::Matrix2d p = Eigen::Matrix2d::Identity();
  for (int i = 0; i < static_cast<int>(fan.face.size()); ++i) {
    const EdgeGluing& g = gluing[fan.edge[i]];
    if (g.edge < 0) throw std::logic_error("vertex_jet_product: boundary edge at an interior vertex");
    double a0, b0;
    if (mesh.edge(fan.edge[i]).x == v) {
      // σ_i traverses τ_i from v, so it has the σ1 role: data as stored, at t = 0.
      a0 = eval_poly(g.a, 0.0) / eval_poly(g.c, 0.0);
      b0 = eval_poly(g.b, 0.0) / eval_poly(g.c, 0.0);
    } else {
      // Rule (i) of §1.6: [a + δ₂ b − δ₁ c, c, b](1) with the roles exchanged.
      const double a1 = eval_poly(g.a, 1.0), b1 = eval_poly(g.b, 1.0), c1 = eval_poly(g.c, 1.0);
      a0 = (a1 + (g.triangle2 ? b1 : 0.0) - (g.triangle1 ? c1 : 0.0)) / b1;
      b0 = c1 / b1;
    }
    Eigen::Matrix2d m;
    m << 0.0, 1.0, b0, a0;
    p = m * p;
  }
  return p;
}

namespace {

/// Rank of the syzygy matrix (relative 1e-10): a column-pivoted QR of its transpose, whose pivots
/// reveal the rank of these O(1)-scaled banded (convolution) matrices as the singular values do,
/// at a fraction of the cost of an SVD (this runs once per interior edge).
template <class Matrix>
int syzygy_rank(const Matrix& m) {
  using Transposed = Eigen::Matrix<double, Matrix::ColsAtCompileTime, Matrix::RowsAtCompileTime, 0,
                                   Matrix::MaxColsAtCompileTime, Matrix::MaxRowsAtCompileTime>;
  Eigen::ColPivHouseholderQR<Transposed> qr(Transposed(m.transpose()));
  qr.setThreshold(1e-10);
  return static_cast<int>(qr.rank());
}

}  // namespace

int syzygy_dimension(const EdgeGluing& g, int k) {
  // Unknown monomial coefficients: A (k), B (k+1-δ₂), C (k+1-δ₁); product degree <= k+2.
  const int na = k, nb = k + 1 - (g.triangle2 ? 1 : 0), nc = k + 1 - (g.triangle1 ? 1 : 0);
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(k + 3, na + nb + nc);
  auto add = [&](const Eigen::Vector3d& poly, int offset, int count) {
    for (int j = 0; j < count; ++j)
      for (int d = 0; d < 3; ++d) m(j + d, offset + j) += poly[d];
  };
  add(g.a, 0, na);
  add(g.b, na, nb);
  add(g.c, na + nb, nc);
  // Called once per interior edge: for the degrees the space allows (k <= 10) a matrix type with
  // bounded size keeps the decomposition's workspace off the heap.
  using Bounded = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 13, 32>;
  const int rank = k <= 10 ? syzygy_rank(Bounded(m)) : syzygy_rank(m);
  return na + nb + nc - rank;
}

bool crossing_at(const PatchMesh& mesh, const std::vector<EdgeGluing>& gluing, int e, int v) {
  const EdgeGluing& g = gluing[e];
  if (g.edge < 0) return false;
  return mesh.edge(e).x == v ? g.crossing_x : g.crossing_y;
}

}  // namespace iga
