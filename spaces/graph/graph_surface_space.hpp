#pragma once
/// @file
/// A graph surface z = g(x, y) over a planar domain, with any planar space lifted onto it: the
/// functions are those of the planar space, N_i ∘ π (π the projection (x, y, z) ↦ (x, y)), and
/// the surface is exact (g symbolic, its derivatives too), so rates are not hidden behind a
/// geometric error.
///
/// Evaluation: the planar evaluator's physical derivatives in (x, y) play the reference
/// derivatives of the lift X(x, y) = (x, y, g(x, y)), whose jets are X_x = (1, 0, g_x),
/// X_y = (0, 1, g_y), X_ab = (0, 0, g_ab); spaces/surface_values.hpp turns them into the surface
/// gradient J G⁻¹ ∇φ and the covariant Hessian. PointValues::jacobian3 is the composed map
/// d(x, y, z)/d(ξ, η) = J_X J_planar (the area element of the element's reference cell), and
/// PointValues::jacobian keeps the planar one, so that the planar boundary machinery (edge
/// lengths, outward normals in the plane) still runs on the lifted edges. A planar space with
/// continuity C^k gives C^k functions on the surface (the lift is smooth).

#include <memory>

#include "config/expression.hpp"
#include "spaces/lifted_space.hpp"
#include "spaces/space.hpp"

namespace iga {

class GraphSurfaceSpace final : public Space, public LiftedSpace {
 public:
  /// `height` in x and y. The planar space must be planar (ambient dimension 2).
  GraphSurfaceSpace(SpacePtr planar, const SymbolicFunction& height, const std::string& height_text);

  std::unique_ptr<Evaluator> make_evaluator() const override;
  void element_dofs(int element, std::vector<int>& out) const override { planar_->element_dofs(element, out); }
  RulePtr quadrature(int element, int degree) const override { return planar_->quadrature(element, degree); }
  RulePtr edge_quadrature(int element, int edge, int degree) const override {
    return planar_->edge_quadrature(element, edge, degree);
  }
  std::vector<InteriorEdge> interior_edges() const override { return planar_->interior_edges(); }

  const Space& planar() const override { return *planar_; }
  Eigen::Vector3d lift(const Point2& p) const override;
  Eigen::Matrix<double, 3, 2> lift_jacobian(const Point2& p) const override;
  /// Rows g, g_x, g_y, g_xx, g_xy, g_yy at the planar points (6 × q).
  void height_jets(const Eigen::Matrix2Xd& points, Eigen::MatrixXd& values) const { height_.evaluate(points, values); }

 private:
  SpacePtr planar_;
  FunctionBatch height_;  ///< g, g_x, g_y, g_xx, g_xy, g_yy
};

}  // namespace iga
