#include "spaces/g1/edge_rows.hpp"

#include <algorithm>
#include <cmath>

#include "spaces/g1/bernstein_face.hpp"

namespace iga {

void add_edge_rows(const PatchMesh& mesh, int k, int face, int e, int skip_start, int skip_end,
                   std::vector<std::pair<int, int>>& out) {
  const CellShape shape = mesh.shape(face);
  for (int r = 0; r <= 1; ++r)
    for (int m = skip_start; m <= edge_row_last(shape, k, r) - skip_end; ++m)
      out.push_back({face, edge_coefficient(shape, k, e, m, r)});
}

EdgeCollocation::EdgeCollocation(int k) : degree(k), points(gauss_legendre(k + 3)) {
  for (CellShape shape : {CellShape::quadrilateral, CellShape::triangle}) {
    const int n = shape == CellShape::triangle ? 3 : 4;
    for (int e = 0; e < n; ++e)
      for (bool reversed : {false, true}) {
        // As edge_frame: start X_loc and tangent Y_loc - X_loc on the face.
        const Point2 start = reference_corner(shape, reversed ? e + 1 : e);
        const Point2 tangent = reference_corner(shape, reversed ? e : e + 1) - start;
        std::vector<Eigen::MatrixXd>& j = jets[slot(shape, e, reversed)];
        for (const Point2& p : points.points) j.push_back(bernstein_jet(shape, k, start + p.x() * tangent));
      }
  }
}

std::vector<std::vector<FaceCoefficient>> edge_constraint_rows(const PatchMesh& mesh, const EdgeGluing& g, int k) {
  return edge_constraint_rows(mesh, g, EdgeCollocation(k));
}

std::vector<std::vector<FaceCoefficient>> edge_constraint_rows(const PatchMesh& mesh, const EdgeGluing& g,
                                                               const EdgeCollocation& tables) {
  const int k = tables.degree;
  const MeshEdge& me = mesh.edge(g.edge);
  const EdgeFrame fr = edge_frame(mesh, g.edge);
  const int e1 = me.first.local_edge, e2 = me.second.local_edge;
  const CellShape s1 = mesh.shape(fr.face1), s2 = mesh.shape(fr.face2);
  std::vector<std::vector<FaceCoefficient>> rows;
  rows.reserve(2 * k + 4);
  // C0: straight edges parametrised linearly from X to Y on both faces, so traces match coefficient
  // by coefficient (the second face runs Y -> X).
  for (int m = 0; m <= k; ++m)
    rows.push_back(
        {{fr.face1, edge_coefficient(s1, k, e1, m, 0), 1.0}, {fr.face2, edge_coefficient(s2, k, e2, k - m, 0), -1.0}});
  // G1 by collocation: the residual has degree <= k+2 in t.
  std::vector<std::pair<int, int>> near1, near2;
  add_edge_rows(mesh, k, fr.face1, e1, 0, 0, near1);
  add_edge_rows(mesh, k, fr.face2, e2, 0, 0, near2);
  const auto& jets1 = tables.jets[EdgeCollocation::slot(s1, e1, false)];
  const auto& jets2 = tables.jets[EdgeCollocation::slot(s2, e2, true)];
  for (int p = 0; p < tables.points.size(); ++p) {
    const double t = tables.points.points[p].x();
    const Eigen::MatrixXd& j1 = jets1[p];
    const Eigen::MatrixXd& j2 = jets2[p];
    const double a = eval_poly(g.a, t), b = eval_poly(g.b, t), c = eval_poly(g.c, t);
    std::vector<FaceCoefficient> row;
    row.reserve(near1.size() + near2.size());
    double big = 0.0;
    for (const auto& [f1, i] : near1) {
      const double cross = j1(1, i) * fr.cross1.x() + j1(2, i) * fr.cross1.y();
      const double along = j1(1, i) * fr.tangent1.x() + j1(2, i) * fr.tangent1.y();
      const double v = c * cross - a * along;
      if (v != 0.0) row.push_back({fr.face1, i, v});
      big = std::max(big, std::abs(v));
    }
    for (const auto& [f2, i] : near2) {
      const double v = -b * (j2(1, i) * fr.cross2.x() + j2(2, i) * fr.cross2.y());
      if (v != 0.0) row.push_back({fr.face2, i, v});
      big = std::max(big, std::abs(v));
    }
    for (FaceCoefficient& fc : row) fc.value /= big;
    rows.push_back(std::move(row));
  }
  return rows;
}

}  // namespace iga
