#pragma once
/// @file
/// Chain rule from reference to physical derivatives, including the second derivatives of the
/// geometry map (needed for non-affine elements: mapped patches, bilinear quads, curved cells).

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

#include "spaces/element_core.hpp"
#include "spaces/space.hpp"

namespace iga {

/// A map (xi, eta) -> (x, y) and its first and second derivatives at one point.
struct GeometryJet {
  Point2 x = Point2::Zero();
  Eigen::Matrix2d jacobian = Eigen::Matrix2d::Identity();  ///< J(i, k) = d x_i / d xi_k
  Eigen::Matrix2d hessian_x = Eigen::Matrix2d::Zero();     ///< d^2 x / d xi_k d xi_l
  Eigen::Matrix2d hessian_y = Eigen::Matrix2d::Zero();     ///< d^2 y / d xi_k d xi_l
};

/// Reference-coordinate data of n functions at q points (arrays n x q).
struct ReferenceDerivatives {
  Eigen::MatrixXd value, dxi, deta, dxixi, dxieta, detaeta;
};

/// The reference data of an element's active functions from the tables of its local basis at the
/// q points (value, d/dxi, d/deta, d²/dxi², d²/dxi deta, d²/deta²; local x q each) and its
/// extraction (active x local, element_core.hpp): only what `flags` asks for (hessians imply gradients).
void extract_reference_derivatives(const Extraction& extraction, const LocalTables& tables, unsigned flags,
                                   ReferenceDerivatives& ref);

/// The reference data of one function Σ_l c_l φ_l from its local coefficients (C_eᵀ times the
/// active ones, or those themselves when the extraction is the identity): one row per table,
/// instead of extracting every active function at every point.
void contract_local_derivatives(const LocalTables& tables, const Eigen::VectorXd& local, unsigned flags,
                                ReferenceDerivatives& one);

/// out.x and out.jacobian from the geometry jets alone (an evaluator's evaluate_geometry).
void take_geometry(const std::vector<GeometryJet>& jets, PointValues& out);

/// Row 0 of the physical arrays of `single` (one function pushed forward) into `out`, and its
/// points and Jacobians (on surfaces also normals and mean curvature) into `geometry`.
void take_single_function(const PointValues& single, unsigned flags, PointValues& geometry, FunctionValues& out);

/// Fill out.x, out.jacobian and the physical arrays requested by `flags` from reference data and
/// the geometry jets at the q points. out.dofs is left untouched.
void push_forward(const std::vector<GeometryJet>& geometry, const ReferenceDerivatives& ref, unsigned flags,
                  PointValues& out);

}  // namespace iga
