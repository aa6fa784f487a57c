#pragma once
/// @file
/// Built-in surfaces of revolution as exact NURBS patches (NurbsSurfaceMap), for the surface
/// problems and the shell benchmarks: a profile curve in the (ρ, z) half-plane swept by a circular
/// arc about the z axis, P_ij = (ρ_j c_i, z_j), w_ij = w_i ω_j (the standard exact construction).
/// Circular arcs are rational quadratics of at most 90° each (middle weight cos(Δ/2)); equal
/// pieces meet C1 in the parameter (the map is C1, not C2, at their joints).
///
/// Parameter directions: u runs around the axis (azimuth), v along the profile.

#include <memory>

#include "spaces/surface_patch/nurbs_surface_map.hpp"

namespace iga {

/// Cylinder of `radius` about the x axis, x ∈ [0, length]: (x, y, z) = (s, R sin θ, R cos θ), so
/// θ = 0 is the crown z = R. half_angle_degrees ≥ 180: the closed cylinder, periodic in θ (u);
/// otherwise the sector |θ| ≤ half_angle (Scordelis–Lo: 40°). Throws InputError on R, L ≤ 0.
std::shared_ptr<const NurbsSurfaceMap> nurbs_cylinder(double radius, double length, double half_angle_degrees);

/// Torus about the z axis: ((R + r cos φ) cos θ, (R + r cos φ) sin θ, r sin φ), periodic in θ (u)
/// and φ (v). Throws InputError unless 0 < r < R.
std::shared_ptr<const NurbsSurfaceMap> nurbs_torus(double major_radius, double minor_radius);

/// Sphere zone of `radius` about the z axis between the polar angles hole_degrees (> 0: the pole is
/// a singular point of the map) and 90° (the equator): the hemisphere z ≥ 0 with a polar hole.
/// sweep_degrees = 360: periodic in the azimuth; less: the sector 0 ≤ θ ≤ sweep (a quarter for
/// symmetric shell models). Throws InputError on radius ≤ 0, hole outside (0, 90), sweep outside (0, 360].
std::shared_ptr<const NurbsSurfaceMap> nurbs_sphere_zone(double radius, double hole_degrees, double sweep_degrees);

}  // namespace iga
