#pragma once
/// @file
/// Quadrature on a piece of an element's edge, for the forms that integrate over interior edges
/// (the estimator's jump terms, the C0 interior penalty): both sides of an edge are evaluated by
/// their own elements at the same physical points.

#include "quadrature/quadrature_rule.hpp"
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

}  // namespace iga
