#pragma once
/// @file
/// Quadrature on a piece of an element's edge, for the forms that integrate over interior edges
/// (the estimator's jump terms, the C0 interior penalty): both sides of an edge are evaluated by
/// their own elements at the same physical points.

#include <Eigen/Geometry>
#include <vector>

#include "quadrature/quadrature_rule.hpp"
#include "spaces/point_values.hpp"
#include "spaces/space.hpp"

namespace iga {

/// The points of `line` (a rule on [0, 1]) on the sub-range [t0, t1] of edge `edge` of a reference
/// cell, with the line's weights (the caller scales by the piece's length).
inline QuadratureRule points_on_edge(CellShape shape, int edge, double t0, double t1, const QuadratureRule& line) {
  QuadratureRule out;
  out.degree = line.degree;
  out.weights = line.weights;
  for (const Point2& s : line.points) out.points.push_back(reference_edge_point(shape, edge, t0 + s.x() * (t1 - t0)));
  return out;
}

/// The outward unit conormal of the element at point q of its edge `edge`: the edge tangent of the
/// (counterclockwise) reference cell pushed forward, crossed with the unit normal J_ξ × J_η of the
/// same orientation, so ν points out of the element whatever the surface's global orientation.
inline Eigen::Vector3d outward_conormal(const PointValues& g, int q, CellShape shape, int edge) {
  const Eigen::Matrix<double, 3, 2>& J = g.jacobian3[q];
  const Point2 t = reference_edge_tangent(shape, edge);
  const Eigen::Vector3d tangent = J * Eigen::Vector2d(t.x(), t.y());
  const Eigen::Vector3d normal = J.col(0).cross(J.col(1)).normalized();
  return tangent.cross(normal).normalized();
}

/// The points of both sides of every edge piece, side a and side b, at the same physical points.
/// Kept alive by the caller for the whole loop: evaluators may cache tables by a rule's address.
struct EdgeSideRules {
  std::vector<QuadratureRule> a, b;
};
inline EdgeSideRules edge_side_rules(const Space& space, const std::vector<InteriorEdge>& edges,
                                     const QuadratureRule& line) {
  EdgeSideRules r;
  r.a.reserve(edges.size());
  r.b.reserve(edges.size());
  for (const InteriorEdge& e : edges) {
    r.a.push_back(points_on_edge(space.cell_shape(e.element_a), e.edge_a, e.a0, e.a1, line));
    r.b.push_back(points_on_edge(space.cell_shape(e.element_b), e.edge_b, e.b0, e.b1, line));
  }
  return r;
}

}  // namespace iga
