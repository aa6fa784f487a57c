#include "geometry/rsd/surface_measures.hpp"

#include <Eigen/Geometry>
#include <cmath>

#include "geometry/surface_jet.hpp"
#include "quadrature/quadrature_rule.hpp"

namespace iga::rsd {

SurfacePoint surface_point(const BezierTriangle& patch, double xi, double eta) {
  const Eigen::Vector3d t(1 - xi - eta, xi, eta);
  const auto d = patch.partials(t);
  return {patch.value(t), d[1] - d[0], d[2] - d[0]};
}

AreaVolume area_and_volume(const RsdSurface& surface, int quadrature_degree) {
  const QuadratureRule rule = triangle_rule(quadrature_degree);
  AreaVolume result;
  for (const auto& patch : surface.patches)
    for (int q = 0; q < rule.size(); ++q) {
      const SurfacePoint p = surface_point(patch, rule.points[q][0], rule.points[q][1]);
      // The oriented area vector x_ξ × x_η = √det G n of the patch map.
      const double area = area_element(p.x_xi, p.x_eta);
      result.area += rule.weights[q] * area;
      result.volume += rule.weights[q] * p.x.dot(area * unit_normal(p.x_xi, p.x_eta)) / 3.0;
    }
  return result;
}

SphereDeviation sphere_deviation(const RsdSurface& surface, const Eigen::Vector3d& center, double radius) {
  SphereDeviation d;
  auto radial = [&](const Eigen::Vector3d& x) { d.radial = std::max(d.radial, std::abs((x - center).norm() - radius)); };
  const int n = 10;
  for (const auto& patch : surface.patches)
    for (int a = 0; a <= n; ++a)
      for (int b = 0; a + b <= n; ++b) {
        const SurfacePoint p = surface_point(patch, double(a) / n, double(b) / n);
        radial(p.x);
        const Eigen::Vector3d normal = unit_normal(p.x_xi, p.x_eta), r = p.x - center;
        const double angle = std::atan2(normal.cross(r).norm(), normal.dot(r));
        d.normal_degrees = std::max(d.normal_degrees, angle * 180.0 / M_PI);
      }
  for (const auto& e : surface.edges)
    for (int q = 0; q <= 20; ++q) {
      Eigen::Vector3d t = Eigen::Vector3d::Zero();
      t[surface.local_index(e.n, e.i)] = q / 20.0;
      t[surface.local_index(e.n, e.j)] = 1 - q / 20.0;
      radial(surface.patches[e.n].value(t));
    }
  return d;
}

}  // namespace iga::rsd
