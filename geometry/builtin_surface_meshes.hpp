#pragma once
/// @file
/// Built-in triangle surface meshes with their normals (the fixtures of the RSD construction).

#include "geometry/triangle_surface_mesh.hpp"

namespace iga {

/// Icosahedron inscribed in the unit sphere, subdivided `level` times (each triangle into four,
/// midpoints projected onto the sphere); exact sphere normals n = p. 20·4^level triangles.
TriangleSurfaceMesh icosphere(int level);

/// Regular octahedron with vertices ±e_x, ±e_y, ±e_z; normals n = p.
TriangleSurfaceMesh regular_octahedron();

/// Regular tetrahedron (1,1,1), (1,−1,−1), (−1,1,−1), (−1,−1,1); fan normals (= n ∝ p).
TriangleSurfaceMesh regular_tetrahedron();

/// The octahedron with rational perturbations of the RSD note (§5.3): generic geometry of
/// valence 4, with fan (area-weighted) normals.
TriangleSurfaceMesh perturbed_octahedron();

/// Open height field of the RSD note (§5.4): 4×4 grid on x, y ∈ {−3/4, −1/4, 1/4, 3/4} over
/// z = x²/2 − y²/3 + xy/5, alternating ("union jack") diagonals, 18 triangles, exact normals.
TriangleSurfaceMesh height_field();

/// Fan normals: Σ over the incident triangles of (p_b − p_i) × (p_c − p_i), normalised (the
/// paper's normal guess, twice the area-weighted normal). Needs a consistently oriented mesh.
std::vector<Eigen::Vector3d> fan_normals(const TriangleSurfaceMesh& mesh);

}  // namespace iga
