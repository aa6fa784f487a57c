#include "spaces/g1_4split/fan_values.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <set>

#include "spaces/g1_4split/g1_4split_basis.hpp"
#include "spaces/g1_4split/g1_4split_meshes.hpp"

namespace iga {

namespace {

double det(const Point2& a, const Point2& b) { return a.x() * b.y() - a.y() * b.x(); }

}  // namespace

std::vector<std::map<int, double>> fan_gluing_values(const PatchMesh& mesh, const QuadTopology& t) {
  std::vector<std::map<int, double>> out(t.num_vertices());
  for (int v = 0; v < t.num_vertices(); ++v) {
    const bool boundary = t.vertex_on_boundary(v);
    std::vector<int> edges = t.vertex_edges(v);
    const int n = static_cast<int>(edges.size());
    if ((boundary && t.vertex_faces(v) < 2) || n < 3) continue;
    auto dir = [&](int e) {
      const int w = t.edge(e).g0 == v ? t.edge(e).g1 : t.edge(e).g0;
      return Point2(mesh.vertex(w) - mesh.vertex(v));
    };
    std::sort(edges.begin(), edges.end(), [&](int a, int b) {
      return std::atan2(dir(a).y(), dir(a).x()) < std::atan2(dir(b).y(), dir(b).x());
    });
    // Face sectors: pairs of edges meeting at a face corner.
    std::set<std::pair<int, int>> sectors;
    for (const auto& [f, c] : t.vertex_corners(v)) {
      const int a = t.face_edge(f, c), b = t.face_edge(f, (c + 3) % 4);
      sectors.emplace(std::min(a, b), std::max(a, b));
    }
    auto is_sector = [&](int a, int b) { return sectors.count({std::min(a, b), std::max(a, b)}) > 0; };
    if (boundary) {  // start after the exterior gap: u_0 and u_F are the boundary edges
      int gap = -1;
      for (int i = 0; i < n; ++i)
        if (!is_sector(edges[i], edges[(i + 1) % n])) gap = i;
      if (gap < 0) continue;
      std::rotate(edges.begin(), edges.begin() + (gap + 1) % n, edges.end());
    }
    if (!boundary && n == 4) {
      // b ≡ −1 at valence 4 allows the values (α, 0, −α, 0): one line straight in the fan chart.
      // Straighten the straighter of the two mesh lines, let the other keep its bend α.
      // Edge vectors, not directions: at valence 4 the areas leave the speed ratio of the two
      // lines free, and the bilinear map's own ratio is the one that keeps it in the space.
      std::vector<Point2> d(4);
      bool ok = true;
      for (int i = 0; i < 4; ++i) d[i] = dir(edges[i]);
      for (int i = 0; i < 4; ++i) ok = ok && is_sector(edges[i], edges[(i + 1) % 4]) && det(d[i], d[(i + 1) % 4]) > 0;
      if (!ok) continue;
      auto bend = [&](int i) { return std::abs(det(d[i].normalized(), d[i + 2].normalized())); };
      const int s = bend(0) <= bend(1) ? 0 : 1;  // the straighter line: edges s, s + 2
      const Point2 w = 0.5 * (d[s] - d[s + 2]);
      const Point2 &p = d[s + 1], &q = d[(s + 3) % 4];  // the other line, p after w ccw
      if (det(w, p) <= 0 || det(q, w) <= 0) continue;
      const double c = std::sqrt(det(w, p) * det(q, w));  // equal areas, lengths kept on average
      std::vector<Point2> u(4);
      u[s] = w;
      u[s + 2] = -w;
      u[s + 1] = p * (c / det(w, p));
      u[(s + 3) % 4] = q * (c / det(q, w));
      for (int i = 0; i < 4; ++i) {
        double A = det(u[(i + 3) % 4], u[(i + 1) % 4]) / det(u[(i + 3) % 4], u[i]);
        if (std::abs(A) < 1e-12) A = 0.0;
        out[v][edges[i]] = A;
      }
      continue;
    }
    const int sectors_count = boundary ? n - 1 : n;
    // l_{i-1} + l_i = -log s_i for every sector (i-1, i), c = 1.
    Eigen::MatrixXd M = Eigen::MatrixXd::Zero(sectors_count, n);
    Eigen::VectorXd r(sectors_count);
    bool ok = true;
    for (int i = 1; i <= sectors_count; ++i) {
      const int a = edges[i - 1], b = edges[i % n];
      const double s = det(dir(a), dir(b));
      ok = ok && is_sector(a, b) && s > 0;
      M(i - 1, i - 1) = 1;
      M(i - 1, i % n) += 1;
      r(i - 1) = ok ? -std::log(s) : 0.0;
    }
    if (!ok) continue;
    const Eigen::VectorXd l = M.completeOrthogonalDecomposition().solve(r);
    if ((M * l - r).norm() > 1e-9 * std::max(1.0, r.norm())) continue;  // even valence: no equal-area fan
    std::vector<Point2> u(n);
    for (int i = 0; i < n; ++i) u[i] = std::exp(l(i)) * dir(edges[i]);
    for (int i = boundary ? 1 : 0; i < (boundary ? n - 1 : n); ++i) {
      const Point2 &prev = u[(i + n - 1) % n], &next = u[(i + 1) % n];
      double A = det(prev, next) / det(prev, u[i]);
      if (std::abs(A) < 1e-12) A = 0.0;
      out[v][edges[i]] = A;
    }
  }
  return out;
}

std::vector<SplitGluing> planar_line_gluing(const PatchMesh& mesh, const QuadTopology& t, LineGluingReport* report) {
  const std::vector<double> A = symmetric_vertex_values(t, vertex_angles(mesh));
  const std::vector<std::map<int, double>> fan = fan_gluing_values(mesh, t);
  const EndValue value = [&](int v, int e) {
    const auto it = fan[v].find(e);
    return it != fan[v].end() ? it->second : A[v];
  };
  std::vector<SplitGluing> g = vertexwise_gluing(t, value, report);
  return g.empty() ? line_gluing(t, A, report) : g;
}

}  // namespace iga
