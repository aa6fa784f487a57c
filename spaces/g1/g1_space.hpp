#pragma once
/// @file
/// G1Space: the C1 space S¹_k(M) ∘ G⁻¹ on a planar multipatch mesh of bilinear quads and affine
/// triangles (notes §7, route A: gluing data derived from the geometry). One polynomial of
/// bidegree (k,k) per quad and of total degree k per triangle,
/// C1 across all interior edges; the basis is the local-nullspace basis of g1_basis.hpp, stored as
/// a sparse extraction onto each face's Bernstein basis.
///
/// Elements are the mesh faces, with the reference square or triangle and the face's map; the active
/// functions of an element are G1Basis::face_dofs in that order.

#include <map>
#include <memory>
#include <mutex>

#include "spaces/gauss_rule_cache.hpp"
#include "spaces/g1/g1_basis.hpp"
#include "spaces/g1/gluing_data.hpp"
#include "spaces/g1/patch_mesh.hpp"
#include "spaces/space.hpp"

namespace iga {

class G1Space final : public Space {
 public:
  /// Build on `mesh` with degree k. Throws InputError when k is below the degree the local
  /// construction needs on this mesh (the message names the smallest degree that works).
  G1Space(std::shared_ptr<const PatchMesh> mesh, int k);

  /// Facts: type "g1", parameters degree, patches (faces), domain; C1 in physical coordinates by
  /// construction (route A); boundary parts: the sides of the domain's bounding box that boundary
  /// edges lie on, `left` (x = x_min), `right`, `bottom` (y = y_min), `top`, only the nonempty
  /// ones, or the mesh's groups (boundary_parts.hpp).
  std::unique_ptr<Evaluator> make_evaluator() const override;
  void element_dofs(int element, std::vector<int>& out) const override { out = basis_.face_dofs[element]; }

  RulePtr quadrature(int element, int degree) const override;
  RulePtr edge_quadrature(int element, int edge, int degree) const override;

  /// Every interior edge of the mesh once (the g1_jump check samples 2k + 4 points of each: the
  /// jump times both Jacobian determinants is a polynomial of degree <= k + 2 along an edge).
  std::vector<InteriorEdge> interior_edges() const override;

  const PatchMesh& mesh() const { return *mesh_; }
  const std::vector<EdgeGluing>& gluing() const { return gluing_; }
  const G1Basis& basis() const { return basis_; }

 private:
  std::shared_ptr<const PatchMesh> mesh_;
  std::vector<EdgeGluing> gluing_;
  G1Basis basis_;

  GaussRuleCache rules_;
};

}  // namespace iga
