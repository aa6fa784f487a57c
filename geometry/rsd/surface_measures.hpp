#pragma once
/// @file
/// Integrals and deviations of an RSD surface: area, enclosed volume (closed, outward-oriented
/// meshes), and the deviation from a sphere (the icosphere geometry study, note §5.6).

#include "geometry/rsd/rsd_surface.hpp"

namespace iga::rsd {

/// Tangents on the reference triangle (ξ, η) ↦ barycentrics (1 − ξ − η, ξ, η).
struct SurfacePoint {
  Eigen::Vector3d x, x_xi, x_eta;
};
SurfacePoint surface_point(const BezierTriangle& patch, double xi, double eta);

/// Area Σ_n ∫ |F_ξ × F_η| and enclosed volume (1/3) Σ_n ∫ F · (F_ξ × F_η), with the symmetric
/// triangle rule exact for polynomial degree `quadrature_degree` (27 matches the note's 14×14
/// Duffy–Gauss points; the integrands are smooth but not polynomial).
struct AreaVolume {
  double area = 0, volume = 0;
};
AreaVolume area_and_volume(const RsdSurface& surface, int quadrature_degree = 27);

/// Max deviation from the sphere |x − c| = r: radial error max ||F − c| − r| and normal error
/// (degrees) max angle between F_ξ × F_η and F − c, sampled at the 66 points of the degree-10
/// lattice of every patch and at t = k/20 on every edge.
struct SphereDeviation {
  double radial = 0, normal_degrees = 0;
};
SphereDeviation sphere_deviation(const RsdSurface& surface, const Eigen::Vector3d& center = Eigen::Vector3d::Zero(),
                                 double radius = 1.0);

}  // namespace iga::rsd
