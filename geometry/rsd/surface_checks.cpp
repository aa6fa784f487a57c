#include "geometry/rsd/surface_checks.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <limits>

namespace iga::rsd {

namespace {

/// Barycentric point and the two derivative directions of edge e inside triangle n (opposite k).
struct EdgeInTriangle {
  Eigen::Vector3d point, cross_direction, along;
};

EdgeInTriangle edge_in_triangle(const RsdSurface& s, const SurfaceEdge& e, int n, int k, double t) {
  const int a = s.local_index(n, e.i), b = s.local_index(n, e.j), c = s.local_index(n, k);
  EdgeInTriangle r{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  r.point[a] = t;
  r.point[b] = 1 - t;
  r.cross_direction[c] = 1;  // u_m = p_k − ½(p_i + p_j)
  r.cross_direction[a] = -0.5;
  r.cross_direction[b] = -0.5;
  r.along[b] = 1;  // p_j − p_i
  r.along[a] = -1;
  return r;
}

}  // namespace

EdgeFrame edge_frame(const RsdSurface& s, const SurfaceEdge& e, double t) {
  const auto in_n = edge_in_triangle(s, e, e.n, e.k, t);
  const auto in_nbar = edge_in_triangle(s, e, e.nbar, e.kbar, t);
  EdgeFrame f;
  f.V = s.patches[e.n].derivative(in_n.point, in_n.cross_direction);
  f.E = s.patches[e.n].derivative(in_n.point, in_n.along);
  f.Vbar = s.patches[e.nbar].derivative(in_nbar.point, in_nbar.cross_direction);
  return f;
}

double g1_residual(const EdgeFrame& f) {
  const double scale = f.V.norm() * f.Vbar.norm() * f.E.norm();
  return scale > 0 ? std::abs(f.V.cross(f.Vbar).dot(f.E)) / scale : 0.0;
}

double fold_alpha(const EdgeFrame& f) {
  const Eigen::Vector3d vxe = f.V.cross(f.E);
  return f.Vbar.cross(f.E).dot(vxe) / vxe.squaredNorm();
}

double regularity(const EdgeFrame& f) {
  return std::min(f.V.cross(f.E).norm() / (f.V.norm() * f.E.norm()),
                  f.Vbar.cross(f.E).norm() / (f.Vbar.norm() * f.E.norm()));
}

void measure_surface(RsdSurface& s) {
  RsdReport& r = s.report;
  r.max_g1_residual = 0;
  r.max_fold_alpha = -std::numeric_limits<double>::infinity();
  r.min_regularity = std::numeric_limits<double>::infinity();
  r.max_z = 0;
  for (std::size_t m = 0; m < s.edges.size(); ++m) {
    const SurfaceEdge& e = s.edges[m];
    for (int q = 0; q <= 20; ++q) {
      const double t = q / 20.0;
      const auto& z = s.z[m];
      r.max_z = std::max(r.max_z, Eigen::Vector3d(z[0](t), z[1](t), z[2](t)).norm());
    }
    if (!e.interior()) continue;
    for (int q = 1; q < 20; ++q) {
      const EdgeFrame f = edge_frame(s, e, q / 20.0);
      r.max_g1_residual = std::max(r.max_g1_residual, g1_residual(f));
      r.max_fold_alpha = std::max(r.max_fold_alpha, fold_alpha(f));
      r.min_regularity = std::min(r.min_regularity, regularity(f));
    }
  }
  r.interpolation_residual = 0;
  for (int n = 0; n < s.mesh.num_triangles(); ++n) {
    const auto& tri = s.mesh.triangles[n];
    for (int a = 0; a < 3; ++a) {
      const Eigen::Vector3d corner = Eigen::Vector3d::Unit(a);
      const Eigen::Vector3d& f = s.data.f[tri[a]];
      r.interpolation_residual =
          std::max(r.interpolation_residual, (s.patches[n].value(corner) - f).norm() / std::max(1.0, f.norm()));
      for (int b = 0; b < 3; ++b) {
        if (b == a) continue;
        const Eigen::Vector3d direction = Eigen::Vector3d::Unit(b) - Eigen::Vector3d::Unit(a);
        const Eigen::Vector3d& g = s.data.g_of(tri[a], tri[b]);
        r.interpolation_residual = std::max(
            r.interpolation_residual, (s.patches[n].derivative(corner, direction) - g).norm() / g.norm());
      }
    }
  }
}

}  // namespace iga::rsd
