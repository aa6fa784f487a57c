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

  std::unique_ptr<Evaluator> make_evaluator() const override;
  std::string type() const override { return "g1"; }
  /// degree, patches (faces), domain.
  std::vector<std::pair<std::string, std::string>> parameters() const override;

  int dimension() const override { return basis_.dimension(); }
  void element_dofs(int element, std::vector<int>& out) const override { out = basis_.face_dofs[element]; }
  int num_elements() const override { return mesh_->num_faces(); }
  CellShape cell_shape(int element) const override { return mesh_->shape(element); }
  double mesh_size() const override { return mesh_size_; }
  int degree() const override { return basis_.degree; }
  int continuity() const override { return 1; }  // physical C1 by construction (route A)
  bool affine_elements() const override { return affine_; }

  RulePtr quadrature(int element, int degree) const override;
  RulePtr edge_quadrature(int element, int edge, int degree) const override;

  /// Sides of the domain's bounding box that boundary edges lie on: `left` (x = x_min), `right`,
  /// `bottom` (y = y_min), `top`; only the nonempty ones (see boundary_parts.hpp). "all" is implied.
  std::vector<std::string> boundary_names() const override;
  std::vector<BoundaryEdge> boundary_edges(const std::string& name) const override;

  /// Largest physical gradient jump of Σ c_i N_i over every interior interface, sampled at
  /// gradient_jump_samples(k) points per edge (gradient_jump.hpp).
  std::optional<double> max_gradient_jump(const Eigen::VectorXd& coefficients) const override;

  const PatchMesh& mesh() const { return *mesh_; }
  const std::vector<EdgeGluing>& gluing() const { return gluing_; }
  const G1Basis& basis() const { return basis_; }

 private:
  class G1Evaluator;

  std::shared_ptr<const PatchMesh> mesh_;
  std::vector<EdgeGluing> gluing_;
  G1Basis basis_;
  double mesh_size_ = 0.0;
  bool affine_ = false;

  GaussRuleCache rules_;
};

}  // namespace iga
