#pragma once
/// @file
/// The linear Kirchhoff–Love shell as a Formulation (docs/shells.md): the displacement u: Γ → R³
/// in one C1 scalar space per component (3N unknowns in blocks, component c of function i at
/// c·N + i), matrix = membrane + bending energy (assembly/shell_integrators.hpp: tangential
/// calculus with the surface's normal and covariant Hessians, so any C1 surface space of the
/// project carries it), load ∫ f·v per unit area, supports that hold any subset of the
/// displacement components on named boundary parts (each a boundary L2 projection of that
/// component, surface_essential.hpp; zero, or the exact displacement's component when one is
/// given). Errors: L2, H1 (surface gradient) and H2 (covariant Hessian) of the displacement vector,
/// sqrt of the sums of the components' squares.
///
/// A pressure (problem.pressure) is the force p(x) n per area along the normal oriented by
/// spaces/surface_orientation.hpp (outward on a closed surface); the orientation is a note.
///
/// Point loads (problem.point_loads) are located on each level's surface (spaces/
/// surface_point_location.hpp) and add F_c N_i(p) to the load; where each was placed is a note.
///
/// Rigid motions the supports leave free (a free shell: all six; the Scordelis–Lo roof, whose
/// diaphragms hold y and z: the axial translation) are removed as in solver/shell_rigid_motions.hpp:
/// one coefficient pinned per free motion, the M-orthogonal projection onto them subtracted after
/// the solve. The loads must not work on them (resultant force and moment), else an InputError.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "solver/formulation.hpp"
#include "solver/shell_rigid_motions.hpp"
#include "spaces/surface_orientation.hpp"

namespace iga {

class ShellFormulation final : public Formulation {
 public:
  using Formulation::Formulation;
  int components() const override { return 3; }
  void check() const override;
  Eigen::VectorXd load(const WorkShare& share) const override;
  Constraints constraints() const override;
  /// The energy's terms plus, on parts with {rotation: held}, the Nitsche terms holding the rotation.
  SplitMatrix matrix(const std::vector<FormTerm>& terms) const override;
  /// The Nitsche terms of the held rotation, edge by edge (the PETSc assembly's share of them).
  void for_each_extra_element_matrix(const std::vector<int>& elements, const ElementMatrixSink& sink) const override;
  /// The pins are a choice over the whole space and the point loads are located on it: under PETSc
  /// every rank holds the whole space (as for eigenproblems).
  bool works_on_parts() const override { return false; }
  bool has_exact() const override { return problem().shell->exact.has_value(); }
  ErrorNorms errors(const Eigen::VectorXd& coefficients, const WorkShare& share) const override;
  void finish(Eigen::VectorXd& coefficients, const WorkShare& share) const override;
  /// a(u_h, u_h), twice the strain energy: the table's energy and, without an exact solution, its
  /// change between levels (the convergence plot).
  bool reports_energy() const override { return true; }
  Messages messages() const override;
  std::vector<std::string> notes() const override { return notes_; }

  /// The rigid motions the supports leave free (computed once).
  const RigidMotions& free_motions() const;
  /// Their discrete representation and the pinned coefficients (set by constraints()).
  const RigidMotionBasis& rigid_motion_basis() const { return basis_; }
  const std::vector<int>& pinned() const { return pinned_; }

 private:
  /// The oriented normal's sign per element (computed once; InputError at problem.pressure when the
  /// surface has no consistent or no decidable outward normal).
  const SurfaceOrientation& orientation() const;
  /// The boundary edges of the supports for which `holds` is true, each once, in the supports'
  /// order (a part listed twice adds its edges once).
  std::vector<BoundaryEdge> support_edges(const std::function<bool(const ShellSupport&)>& holds) const;
  /// Those of the supports that hold the rotation.
  std::vector<BoundaryEdge> rotation_edges() const;
  /// η = 10 (p + 1)² of the Nitsche terms: above the inverse-inequality constant (docs/shells.md
  /// measures its effect).
  double nitsche_penalty() const { return 10.0 * (space().degree() + 1) * (space().degree() + 1); }

  mutable std::optional<RigidMotions> motions_;
  mutable std::optional<SurfaceOrientation> orientation_;
  mutable RigidMotionBasis basis_;
  mutable std::vector<int> pinned_;
  mutable std::vector<std::string> notes_;
};

}  // namespace iga
