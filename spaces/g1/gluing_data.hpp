#pragma once
/// @file
/// Route A gluing data (notes §7.2): for every interior edge X -> Y of a PatchMesh, the polynomials
/// a, b, c in t = u_X^Y derived from the bilinear / affine geometry by 2x2 determinants, so that
///     c(t) ∂_{X→Z1} f1 = a(t) ∂_{X→Y} f1 + b(t) ∂_{X→Z2} f2          (notes §1.5)
/// holds for every C1 function (f1 on face `first`, f2 on face `second` of the edge).

#include <Eigen/Core>
#include <vector>

#include "spaces/g1/patch_mesh.hpp"

namespace iga {

/// Gluing data of one interior edge. Polynomials are monomial coefficients [p0, p1, p2] in t,
/// scaled so that max(|c(0)|, |c(1)|) = 1 (quad–quad: deg a <= 2, deg b, deg c <= 1; triangle–quad:
/// linear; triangle–triangle: constant).
struct EdgeGluing {
  int edge = -1;
  Eigen::Vector3d a = Eigen::Vector3d::Zero(), b = Eigen::Vector3d::Zero(), c = Eigen::Vector3d::Zero();
  bool triangle1 = false, triangle2 = false;  ///< δ₁, δ₂ of notes §1.6: face `first` / `second` is a triangle
  bool crossing_x = false;  ///< the cross edges of both faces are collinear at X (a(0) = 0)
  bool crossing_y = false;  ///< same at Y (a(1) + δ₂ b(1) − δ₁ c(1) = 0, notes §1.6)
};

/// Value of a monomial coefficient vector at t.
double eval_poly(const Eigen::Vector3d& p, double t);

/// Reference-coordinate data of edge `edge` on its two faces (t runs from X to Y on both):
/// point(t) = start + t * tangent; `cross` is the direction towards the face's other neighbour of X.
struct EdgeFrame {
  int face1 = -1, face2 = -1;
  Point2 start1, tangent1, cross1;  ///< on face `first`: X_loc, Y_loc - X_loc, Z1_loc - X_loc
  Point2 start2, tangent2, cross2;  ///< on face `second`: X_loc, Y_loc - X_loc, Z2_loc - X_loc
};
EdgeFrame edge_frame(const PatchMesh& mesh, int edge);

/// Gluing data of every interior edge (entries for boundary edges have edge = -1), indexed by
/// mesh edge. Checks compatibility (throws std::logic_error naming the edge or vertex when violated):
/// the identity c w1 = a e + b w2, b/c < 0 on [0,1], matching edge tangents from both faces, and
/// Condition 2.6 (the cyclic product of jet matrices is the identity) at every interior vertex.
std::vector<EdgeGluing> gluing_from_geometry(const PatchMesh& mesh);

/// Cyclic product M_F ... M_1 of the first-order jet matrices [[0,1],[b_i(0),a_i(0)]] (a, b divided
/// by c) around interior vertex v, each edge's data rewritten from v by notes §1.6 rule (i)
/// (with the triangle corrections δ₁, δ₂) where v is the edge's Y end. Equals the identity for
/// compatible data.
Eigen::Matrix2d vertex_jet_product(const PatchMesh& mesh, const std::vector<EdgeGluing>& gluing, int v);

/// d_τ(k) = dim{(A,B,C): deg A <= k-1, deg B <= k-δ₂, deg C <= k-δ₁, aA + bB + cC = 0} (notes §2.3,
/// Z_k), by rank.
int syzygy_dimension(const EdgeGluing& g, int k);

/// Whether edge e is crossing at vertex v (one of its ends); false for boundary edges.
bool crossing_at(const PatchMesh& mesh, const std::vector<EdgeGluing>& gluing, int e, int v);

}  // namespace iga
