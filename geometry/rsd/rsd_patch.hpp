#pragma once
/// @file
/// One patch of the RSD surface: the RSD interpolant f_n of a triangle (note §3.1) minus the
/// corrections of its double edges, −½[z(t_a) + z(t_a + t_c)] t_a² t_b² t_c (note §3.3, the
/// paper's symmetric extension; on the edge both terms equal z(t)).

#include <array>
#include <vector>

#include "geometry/rsd/bezier_triangle.hpp"
#include "geometry/rsd/rsd_tuple.hpp"

namespace iga::rsd {

/// The correction of one double edge as seen from a triangle: local positions (0..2) of the
/// edge's smaller vertex i (a), larger vertex j (b) and opposite vertex (c), and z(t), t = λ_i.
struct LocalEdgeCorrection {
  int a = 0, b = 1, c = 2;
  VecPoly<double> z;
};

/// Data of one triangle in its local (mesh) vertex order: f[a] and g[a][b] (g[a][a] unused).
struct TriangleData {
  std::array<Eigen::Vector3d, 3> f;
  std::array<std::array<Eigen::Vector3d, 3>, 3> g;
};

/// The patch F_n = f_n − Σ corrections in Bernstein form of degree `degree` (≥ the degree of
/// every term: 5/6 for f_n, deg z + 5 for a correction).
BezierTriangle rsd_patch(RsdTuple tuple, const TriangleData& data, const std::vector<LocalEdgeCorrection>& corrections,
                         int degree);

}  // namespace iga::rsd
