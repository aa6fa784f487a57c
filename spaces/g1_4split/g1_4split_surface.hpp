#pragma once
/// @file
/// Closed (or open) quad meshes in 3D as G1 surfaces: each coordinate of the mesh's C0 bilinear
/// surface projected (least squares in the faces' parameters) onto the 4-split G1 space of the
/// mesh's topology. Along every edge the G1 relation holds for x, y and z alike, so the tangent
/// planes of the two faces agree wherever the map is regular.

#include <Eigen/Core>
#include <functional>
#include <vector>

#include "spaces/g1_4split/g1_4split_basis.hpp"
#include "spaces/g1_4split/quad_topology.hpp"

namespace iga {

struct G14Surface {
  G14Basis basis;
  /// Per face the B-spline coefficients of x, y and z ((m+1)² each).
  std::vector<std::array<Eigen::VectorXd, 3>> coefficients;
};

/// Fit the surface of `topology` with corner positions `vertices` (one per vertex of the topology).
/// Throws NotSeparable when the degree is below the separability degree.
G14Surface fit_surface(const QuadTopology& topology, const std::vector<Eigen::Vector3d>& vertices, int degree,
                       Blending blending);
/// Where the facets' points go before the fit: the identity (empty: the bilinear surface itself), or
/// the closest point of an exact surface the mesh's vertices lie on (`fit_onto`), whose shape the fit
/// then approximates instead of the polyhedron's.
using FitTarget = std::function<Eigen::Vector3d(const Eigen::Vector3d&)>;

/// The same with given gluing data and regularity r across the split lines.
G14Surface fit_surface(const QuadTopology& topology, const std::vector<SplitGluing>& gluing,
                       const std::vector<Eigen::Vector3d>& vertices, int degree, int regularity,
                       const FitTarget& onto = {});

/// Point, d/du and d/dv of face f's map at (u, v) (the full jet: geometry/surface_jet.hpp).
std::array<Eigen::Vector3d, 3> face_map_jet(const G14Surface& s, int face, double u, double v);

/// G1 residual: the largest angle-free distance between the two faces' unit normals across every
/// interior edge, min(|n0 - n1|, |n0 + n1|) (orientation-free), sampled at `samples` points per edge.
double surface_normal_jump(const QuadTopology& topology, const G14Surface& s, int samples);

/// Regularity: the smallest |x_u × x_v| over a (samples+1)² grid of every face, divided by the
/// largest (1 for a uniformly parametrized surface, 0 for a singular point).
double surface_regularity(const G14Surface& s, int samples);

/// The unit cube's corners in the vertex order of cube_topology(), and the split tetrahedron's
/// (corners of a regular tetrahedron, edge midpoints, face centres) in split_tetrahedron_topology's order.
std::vector<Eigen::Vector3d> cube_vertices();
std::vector<Eigen::Vector3d> split_tetrahedron_vertices();

}  // namespace iga
