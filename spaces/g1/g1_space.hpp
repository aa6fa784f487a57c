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

#include "spaces/gauss_rule_cache.hpp"
#include "spaces/g1/g1_basis.hpp"
#include "spaces/g1/g1_numbering.hpp"
#include "spaces/g1/gluing_data.hpp"
#include "spaces/g1/patch_mesh.hpp"
#include "spaces/builds_on_elements.hpp"
#include "spaces/space.hpp"

namespace iga {

class G1Space final : public Space, public BuildsOnElements {
 public:
  /// Build on `mesh` with degree k. Throws InputError when k is below the degree the local
  /// construction needs on this mesh (the message names the smallest degree that works).
  /// With SpaceExtent::skeleton the space keeps no extraction (BuildsOnElements), only the
  /// numbering (g1_numbering.hpp: a few ints per edge, vertex and face): it solves every local
  /// problem to count and check its functions, one vertex fan at a time, and keeps none (nor the
  /// gluing data); the same input errors as the whole construction, with the same messages, on
  /// every rank.
  G1Space(std::shared_ptr<const PatchMesh> mesh, int k, SpaceExtent extent = SpaceExtent::whole);

  /// Facts: type "g1", parameters degree, patches (faces), domain; C1 in physical coordinates by
  /// construction (route A); boundary parts: the sides of the domain's bounding box that boundary
  /// edges lie on, `left` (x = x_min), `right`, `bottom` (y = y_min), `top`, only the nonempty
  /// ones, or the mesh's groups (boundary_parts.hpp).
  std::unique_ptr<Evaluator> make_evaluator() const override;
  void element_dofs(int element, std::vector<int>& out) const override;

  RulePtr quadrature(int element, int degree) const override;
  RulePtr edge_quadrature(int element, int edge, int degree) const override;

  /// Every interior edge of the mesh once (the g1_jump check samples 2k + 4 points of each: the
  /// jump times both Jacobian determinants is a polynomial of degree <= k + 2 along an edge).
  std::vector<InteriorEdge> interior_edges() const override;

  /// The space with the extractions of `elements` (increasing) only, sharing mesh, gluing and
  /// numbering: solves the local problems of their edges and corners only.
  SpacePtr build_on(const std::vector<int>& elements) const override;
  bool built_on(int element) const override { return slot_[element] >= 0; }

  const PatchMesh& mesh() const { return *mesh_; }
  /// The gluing data of every edge: kept by the whole space only, else std::logic_error.
  const std::vector<EdgeGluing>& gluing() const;
  /// The whole space's basis, indexed by face (a skeleton's is empty; a space built on some
  /// elements has their entries only, in their order, and no `info`).
  const G1Basis& basis() const { return basis_; }

 private:
  /// `from` (a skeleton or a space built on some of its elements) built on `elements`: their local
  /// problems solved.
  G1Space(const G1Space& from, const std::vector<int>& elements);

  std::shared_ptr<const PatchMesh> mesh_;
  std::shared_ptr<const std::vector<EdgeGluing>> gluing_;  ///< null in skeletons and their parts
  std::shared_ptr<const G1Numbering> numbering_;  ///< skeletons and their parts; null for the whole
  G1Basis basis_;                                 ///< face_dofs, extraction: per built element
  std::vector<int> slot_;                         ///< per face: its entry in basis_, −1 if not built

  GaussRuleCache rules_;
};

}  // namespace iga
