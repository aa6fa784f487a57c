#pragma once
/// @file
/// The linear Kirchhoff–Love shell's two energies as vector-valued integrators (three displacement
/// components on one scalar C1 surface space), in tangential calculus: every quantity is an
/// ambient 3×3 tensor read from PointValues (surface gradient, covariant Hessian, unit normal), so
/// the forms do not depend on a patch's parametrisation and run on any C1 surface space.
///
/// For a displacement u with component gradients ∇_Γu_i (the rows of G = ∇_Γu):
///   membrane strain  ε(u) = sym(P G),               P = I − n nᵀ,
///   bending strain   κ(u) = Σ_i n_i ∇_Γ∇_Γ u_i,      (covariant Hessians of the components)
/// the linearised changes of the metric and of the second fundamental form, pushed forward to
/// ambient tensors: with a_α = ∂_α x, ε_αβ = ½(a_α·u_,β + a_β·u_,α), and since the normal changes by
/// δn = −a^γ (n·u_,γ), δb_αβ = n·u_,αβ + x_,αβ·δn = n·(u_,αβ − Γ^γ_αβ u_,γ), the covariant Hessian of
/// each component contracted with n (docs/shells.md). Rigid motions u = a + ω × x give ε = 0
/// (P Ω P is skew) and κ = −(nᵀΩn) W = 0.
///
/// Isotropic Saint-Venant–Kirchhoff material (plane stress), a(u, v) =
///   ∫ Et/(1−ν²) [(1−ν) ε(u):ε(v) + ν tr ε(u) tr ε(v)] + Et³/(12(1−ν²)) [(1−ν) κ(u):κ(v) + ν tr κ(u) tr κ(v)] dA.
/// Element matrices are (3n)², rows in blocks of the n functions per component (assembled by an
/// Assembler of 3 components, assembler.hpp),
/// computed in double; the long double and double-double versions are that matrix converted (the
/// shell is not conditioned like h⁻⁴ in its membrane part, and the pipeline sums it in double).

#include <memory>

#include "assembly/integrator.hpp"

namespace iga {

/// E, ν and the thickness t of a shell.
struct ShellMaterial {
  double youngs_modulus = 1.0;
  double poisson_ratio = 0.0;
  double thickness = 1.0;
  /// Et/(1 − ν²) and D = Et³/(12(1 − ν²)).
  double membrane_stiffness() const;
  double bending_stiffness() const;
};

enum class ShellEnergy { membrane, bending };

/// ∫ Et/(1−ν²)[(1−ν) ε:ε + ν tr ε tr ε] (membrane) or D [(1−ν) κ:κ + ν tr κ tr κ] (bending).
std::shared_ptr<const Integrator> shell_integrator(ShellEnergy part, const ShellMaterial& material);

/// The strains of the basis function N_i e_c at point k of `v` (tests, error norms): ε or κ.
Eigen::Matrix3d membrane_strain(const PointValues& v, int i, int c, int k);
Eigen::Matrix3d bending_strain(const PointValues& v, int i, int c, int k);

}  // namespace iga
