#pragma once
/// @file
/// A capability of spaces on a surface that is the lift of a planar domain (graph surfaces z = g(x,
/// y), spaces/graph/): the functions are those of a planar space composed with the projection onto
/// the plane, and the surface's boundary is the lift of the planar boundary. Essential conditions
/// on such a surface are the planar space's own (boundary_conditions.hpp), with the data pulled
/// back through the lift: u and ∇_Γu on the lifted boundary ⇔ u ∘ X and ∇(u ∘ X) on the planar one.
/// Kept off Space (like LocallyRefinable) so that the interface lists only what every space answers.

#include <Eigen/Core>

#include "spaces/space.hpp"

namespace iga {

class LiftedSpace {
 public:
  virtual ~LiftedSpace() = default;
  /// The planar space whose functions this space carries (same global numbering and elements).
  virtual const Space& planar() const = 0;
  /// The lift X(x, y) of a planar point and its Jacobian dX/d(x, y) (3 × 2).
  virtual Eigen::Vector3d lift(const Point2& p) const = 0;
  virtual Eigen::Matrix<double, 3, 2> lift_jacobian(const Point2& p) const = 0;
};

}  // namespace iga
