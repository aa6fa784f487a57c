#include "spaces/g1_4split/g1_4split_surface.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/surface_jet.hpp"
#include "spaces/g1_4split/face_function.hpp"
#include "spaces/g1_4split/g1_4split_geometry.hpp"

namespace iga {

G14Surface fit_surface(const QuadTopology& topology, const std::vector<Eigen::Vector3d>& vertices, int degree,
                       Blending blending) {
  return fit_surface(topology, symmetric_gluing(topology, blending), vertices, degree, 1);
}

G14Surface fit_surface(const QuadTopology& topology, const std::vector<SplitGluing>& gluing,
                       const std::vector<Eigen::Vector3d>& vertices, int degree, int regularity,
                       const FitTarget& onto) {
  G14Surface s;
  s.basis = build_g14_basis(topology, gluing, degree, regularity);
  const SplitBSpline& b = s.basis.bspline;
  const int n = b.size();
  const Eigen::VectorXd g = b.greville();
  // Broken bilinear surface (or its image on the exact surface), two coordinates at a time through
  // project_geometry.
  FaceGeometry xy, z0;
  for (int f = 0; f < topology.num_faces(); ++f) {
    const auto& q = topology.face(f);
    std::vector<double> c[3];
    for (auto& v : c) v.resize(n * n);
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const double u = g(i), v = g(j);
        Eigen::Vector3d p = (1 - u) * (1 - v) * vertices[q[0]] + u * (1 - v) * vertices[q[1]] +
                            u * v * vertices[q[2]] + (1 - u) * v * vertices[q[3]];
        if (onto) p = onto(p);
        for (int d = 0; d < 3; ++d) c[d][i + j * n] = p(d);
      }
    xy.x.push_back(interpolate_face(b, c[0]));
    xy.y.push_back(interpolate_face(b, c[1]));
    z0.x.push_back(interpolate_face(b, c[2]));
    z0.y.push_back(Eigen::VectorXd::Zero(n * n));
  }
  const FaceGeometry pxy = project_geometry(s.basis, xy), pz = project_geometry(s.basis, z0);
  for (int f = 0; f < topology.num_faces(); ++f) s.coefficients.push_back({pxy.x[f], pxy.y[f], pz.x[f]});
  return s;
}

std::array<Eigen::Vector3d, 3> face_map_jet(const G14Surface& s, int face, double u, double v) {
  std::array<Eigen::Vector3d, 3> out;
  for (int d = 0; d < 3; ++d) {
    const auto j = face_jet(s.basis.bspline, s.coefficients[face][d], Point2(u, v));
    for (int r = 0; r < 3; ++r) out[r](d) = j(r);
  }
  return out;
}

double surface_normal_jump(const QuadTopology& t, const G14Surface& s, int samples) {
  double worst = 0.0;
  for (int e = 0; e < t.num_edges(); ++e) {
    const QuadEdge& edge = t.edge(e);
    if (edge.boundary()) continue;
    for (int p = 0; p < samples; ++p) {
      const double tt = double(p) / (samples - 1);
      Eigen::Vector3d normal[2];
      for (int side = 0; side < 2; ++side) {
        const QuadSide sd = edge.sides[side];
        const double sp = t.face(sd.face)[sd.local_edge] == edge.g0 ? tt : 1 - tt;
        const Point2 uv = reference_edge_point(CellShape::quadrilateral, sd.local_edge, sp);
        const auto j = face_map_jet(s, sd.face, uv.x(), uv.y());
        normal[side] = unit_normal(j[1], j[2]);
      }
      worst = std::max(worst, std::min((normal[0] - normal[1]).norm(), (normal[0] + normal[1]).norm()));
    }
  }
  return worst;
}

double surface_regularity(const G14Surface& s, int samples) {
  double lo = 1e300, hi = 0.0;
  for (std::size_t f = 0; f < s.coefficients.size(); ++f)
    for (int j = 0; j <= samples; ++j)
      for (int i = 0; i <= samples; ++i) {
        const auto jet = face_map_jet(s, static_cast<int>(f), double(i) / samples, double(j) / samples);
        const double a = area_element(jet[1], jet[2]);
        lo = std::min(lo, a);
        hi = std::max(hi, a);
      }
  return lo / std::max(hi, 1e-300);
}

std::vector<Eigen::Vector3d> cube_vertices() {
  std::vector<Eigen::Vector3d> v;
  for (int id = 0; id < 8; ++id) v.emplace_back(id & 1, (id >> 1) & 1, (id >> 2) & 1);
  return v;
}

std::vector<Eigen::Vector3d> split_tetrahedron_vertices() {
  // The triangle corners; each edge mid and face centre is the mean of corner 0 (a triangle
  // corner) of the quads at it (split_tetrahedron_topology): the two ends of its edge twice, or
  // the triangle's three corners in order. Sums of ±1, so exact whatever the order.
  const QuadTopology t = split_tetrahedron_topology();
  std::vector<Eigen::Vector3d> v = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  for (int w = 4; w < t.num_vertices(); ++w) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (const auto& [f, c] : t.vertex_corners(w)) sum += v[t.face(f)[0]];
    v.push_back(sum / static_cast<double>(t.vertex_corners(w).size()));
  }
  return v;
}

}  // namespace iga
