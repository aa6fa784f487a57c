#pragma once
/// @file
/// The linear Kirchhoff–Love shell as a Formulation (docs/shells.md): the displacement u: Γ → R³
/// in one C1 scalar space per component (3N unknowns in blocks, component c of function i at
/// c·N + i), matrix = membrane + bending energy (assembly/shell_integrators.hpp: tangential
/// calculus with the surface's normal and covariant Hessians, so any C1 surface space of the
/// project carries it), load ∫ f·v per unit area, supports that hold any subset of the
/// displacement components on named boundary parts (each a boundary L2 projection of that
/// component, surface_dirichlet.hpp; zero, or the exact displacement's component when one is
/// given). Errors: L2, H1 (surface gradient) and H2 (covariant Hessian) of the displacement vector,
/// sqrt of the sums of the components' squares.
///
/// A component that no support holds (the axial one of the Scordelis–Lo roof, whose diaphragms
/// hold y and z) leaves the translation along it in the kernel: its coefficient 0 is pinned (an
/// essential condition like any other; the load must have no resultant along it, else an
/// InputError), which changes that component by a constant only (the constants are in the space:
/// Σ N_i = 1), and the solution is shifted after the solve so that the component has zero mean.
/// Rotations must be held by the supports (else the factorization reports a singular matrix).

#include "solver/formulation.hpp"

namespace iga {

class ShellFormulation final : public Formulation {
 public:
  using Formulation::Formulation;
  int components() const override { return 3; }
  void check() const override;
  Eigen::VectorXd load(const WorkShare& share) const override;
  Constraints constraints() const override;
  bool has_exact() const override { return problem().shell->exact.has_value(); }
  ErrorNorms errors(const Eigen::VectorXd& coefficients, const WorkShare& share) const override;
  void finish(Eigen::VectorXd& coefficients, const WorkShare& share) const override;
  /// a(u_h, u_h), twice the strain energy: the table's energy and, without an exact solution, its
  /// change between levels (the convergence plot).
  bool reports_energy() const override { return true; }
  Messages messages() const override;

 private:
  /// True when some support holds component c.
  bool held(int c) const;
  /// ∫ N_i over the share (set by load; the zero-mean shift of unheld components).
  mutable Eigen::VectorXd mass_of_one_;
};

}  // namespace iga
