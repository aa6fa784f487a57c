#pragma once
/// @file
/// First-order data of the G1 interpolation problem (note §2.3): a point f_i per vertex and a
/// tangent vector g_ij per directed edge (the surface's derivative at p_i towards p_j), and the
/// checks of the solvability conditions (11), (12) and (28).

#include <Eigen/Core>
#include <unordered_map>
#include <vector>

#include "geometry/triangle_surface_mesh.hpp"

namespace iga::rsd {

/// f per vertex, g per directed edge, and the unit normal n_i of the plane the g_ij of vertex i
/// must lie in (condition (28)).
struct FirstOrderData {
  std::vector<Eigen::Vector3d> f;
  std::vector<Eigen::Vector3d> n;
  std::unordered_map<long long, Eigen::Vector3d> g;  ///< key directed_key(i, j)

  static long long directed_key(int i, int j) { return (static_cast<long long>(i) << 32) | static_cast<unsigned>(j); }
  const Eigen::Vector3d& g_of(int i, int j) const { return g.at(directed_key(i, j)); }
  Eigen::Vector3d& g_of(int i, int j) { return g[directed_key(i, j)]; }
};

/// f_i = p_i, n_i = the mesh normal, and g_ij = the projection of the chord p_j − p_i onto the
/// tangent plane n_i^⊥ (the paper's Remark 2).
FirstOrderData projected_chord_data(const TriangleSurfaceMesh& mesh, const std::vector<SurfaceEdge>& edges);

/// Tolerance of the data checks: relative sine of angles and relative out-of-plane components.
inline constexpr double data_tolerance = 1e-9;

/// InputError naming the vertex and edge when
///  (28) some g_ij leaves the tangent plane n_i^⊥ (no G1 surface of this form exists),
///  (11) two tangents g_ij, g_ik of a triangle corner are parallel (singular vertex),
///  (12) at an end of a double edge the tangents towards k and k̄ are not strictly on opposite
///       sides of g_ij (the tangent triangles overlap: a fold is unavoidable),
///  and when the tangents around a vertex wind more than once (the signed corner angles of its
///  fan sum to 4π or more: a branch point, which (12) alone does not exclude).
void check_data_conditions(const TriangleSurfaceMesh& mesh, const std::vector<SurfaceEdge>& edges,
                           const FirstOrderData& data);

}  // namespace iga::rsd
