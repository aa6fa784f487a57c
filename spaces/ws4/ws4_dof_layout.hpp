#pragma once
/// @file
/// The 51 degrees of freedom of a WS4 element in the order of Ws4Space (see ws4_space.hpp):
/// 10 per corner, 6 per edge, 3 interior. Shared by the space and the exact extraction.

#include "quadrature/quadrature_rule.hpp"

namespace iga::ws4::dof_layout {

/// Reference corners P0, P1, P2.
inline const Point2 corner[3] = {Point2(0, 0), Point2(1, 0), Point2(0, 1)};
/// Vertex DOF k = D_{d1}^a D_{d2}^b u with a = vertex_dx[k], b = vertex_dy[k] (frame (d1, d2)).
constexpr int vertex_dx[10] = {0, 1, 0, 2, 1, 0, 3, 2, 1, 0};
constexpr int vertex_dy[10] = {0, 0, 1, 0, 1, 2, 0, 1, 2, 3};
/// Index k of D_{d1}^a D_{d2}^b, [a][b] (a + b <= 3).
constexpr int vertex_index[4][4] = {{0, 2, 5, 9}, {1, 4, 8, -1}, {3, 7, -1, -1}, {6, -1, -1, -1}};
/// Edge DOF k = ∂_n^{edge_order[k]} u(e(edge_s[k])) along the globally oriented edge.
constexpr double edge_s[6] = {0.5, 0.25, 0.75, 0.25, 0.5, 0.75};
constexpr int edge_order[6] = {1, 2, 2, 3, 3, 3};
/// Interior DOFs: u at v3, v1, v2 of the paper (functionals ρ49, ρ50, ρ51), reference coordinates.
inline const Point2 interior_point[3] = {Point2(0.375, 0.25), Point2(0.375, 0.375), Point2(0.25, 0.375)};

constexpr int first_edge_dof = 30, first_interior_dof = 48;

}  // namespace iga::ws4::dof_layout
