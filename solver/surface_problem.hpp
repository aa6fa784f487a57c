#pragma once
/// @file
/// The Laplace–Beltrami problem −Δ_Γu + c u = f (c = `reaction`, default 1) on a surface Γ in 3D,
/// solved on a space with ambient_dimension() == 3: closed surfaces, or open ones with u = g on
/// the whole boundary curve (a boundary L2 projection, assembly/surface_essential.hpp). With an exact solution u given in x, y, z, the source is computed at
/// every quadrature point from the surface's own unit normal n and mean curvature H = div_Γ n:
///   Δ_Γu = Δu − nᵀ(∇²u)n − H ∂_n u,
/// so the surface is the exact geometry of the problem (no geometric error). With c = 0 the solution
/// is unique up to a constant: zero mean, or the exact solution's mean when one is given.

#include "assembly/boundary_conditions.hpp"
#include "assembly/fields.hpp"
#include "config/config_node.hpp"
#include "solver/constant_kernel.hpp"
#include "solver/formulation.hpp"

namespace iga {

/// The given source, else f(x, n, H) = −Δ_Γu + u from the exact solution (laplace_beltrami).
SurfaceSource surface_source(const ProblemSpec& problem);

/// f as a field on the surface's points (its ambient values).
SurfaceField surface_field(const SymbolicFunction& f);

/// u given in x, y, z as callables: u and its ambient gradient, and the ambient Hessian when
/// `with_hessian` (the surface H2 seminorm of fourth-order problems; a shell's components too).
SurfaceExactSolution surface_exact_solution(const SymbolicFunction& u, bool with_hessian);

/// What the two scalar surface problems share: closed surfaces or open ones, on a closed one the
/// constants as the kernel of a problem without reaction (ConstantKernel), and the errors against
/// u given in x, y, z (the surface H2 seminorm too for surface_biharmonic).
class ScalarSurfaceFormulation : public Formulation {
 public:
  using Formulation::Formulation;
  void finish(Eigen::VectorXd& coefficients, const WorkShare& share) const override;
  ErrorNorms errors(const Eigen::VectorXd& coefficients, const WorkShare& share) const override;

 protected:
  bool open() const { return !space().boundary_edges("all").empty(); }
  /// −Δ_Γu = f or Δ_Γ²u = f on a closed surface: u fixed up to a constant (pinned in the solve,
  /// shifted to its mean after). Not for eigenproblems, where the constants are the eigenfunctions
  /// of λ = 0.
  bool pure() const { return problem().reaction == 0 && !open() && !problem().eigen; }
  mutable ConstantKernel kernel_;  ///< pure problems: set by load, used by finish

 private:
  bool works_on_parts() const override { return Formulation::works_on_parts() && !pure(); }
};

/// The Laplace–Beltrami problem as a Formulation: matrix laplace + c mass (ProblemSpec::terms,
/// summed in double: conditioned like h⁻², far from the plates' need), the load from
/// surface_source, Dirichlet data on open surfaces (surface_essential.hpp). Without reaction on a
/// closed surface, constants (Σ N_i = 1) span the kernel: the load is made orthogonal to them
/// (ConstantKernel: the load orthogonal to them, coefficient 0 pinned, the solution shifted to
/// zero mean or to the exact solution's mean).
class SurfaceFormulation final : public ScalarSurfaceFormulation {
 public:
  using ScalarSurfaceFormulation::ScalarSurfaceFormulation;
  void check() const override;
  Eigen::VectorXd load(const WorkShare& share) const override;
  Constraints constraints() const override;
  Messages messages() const override;
};

/// The surface biharmonic problem Δ_Γ²u + c u = f (c = `reaction`, default 1; with c = 0 on a
/// closed surface u is fixed up to a constant as for Laplace–Beltrami: ConstantKernel) on a closed surface, or on an open one whose boundary parts are clamped (u and the
/// conormal derivative ∂_ν u from the exact solution: surface_essential.hpp; lifted graph surfaces
/// through their planar space) or simply supported (u only; Δ_Γu natural: a given source gains
/// ∫ Δ_Γu ∂_ν v over those edges, surface_conormal_load.hpp), every edge one or the other (no free
/// edges), as a Formulation: matrix ∫ Δ_Γu Δ_Γv + c ∫ u v (ProblemSpec::terms: the bilaplace
/// integrator on the covariant Hessians, and mass), on C1 surface spaces. The load is the given
/// source, or with an exact solution u the bilinear form applied to u,
///   ℓ(v) = ∫ Δ_Γu Δ_Γv + c u v,   Δ_Γu = tr ∇²u − n·∇²u n − H ∂_n u   pointwise,
/// element by element with the surface's own n and H: on a G1 surface (curvature jumps across
/// patch edges) Δ_Γu jumps there and the strong form f = Δ_Γ²u + c u would miss the edge terms;
/// the weak load has none to miss, and its solution is u's Galerkin projection. Errors: L2, H1
/// (surface gradient) and the surface H2 seminorm (covariant Hessian).
///
/// On a C0 space with interior edges the form is the C0 interior penalty one
/// (assembly/interior_penalty.hpp): the element integrals plus, over the interior edges, the
/// consistency and symmetry terms and the penalty c0ip_penalty(p) / h_E on the conormal jumps; the
/// load a_h(u, ·) gains the edge term −∫ {Δ_Γu}[∂_ν v]. The study takes it with the serial solvers
/// only, on graph surfaces and on closed RSD surfaces of Π1 patches (solver/study.cpp refuses Π0:
/// its parametrisation spoils the H2 approximation, docs/surface-biharmonic.md).
class SurfaceBiharmonicFormulation final : public ScalarSurfaceFormulation {
 public:
  using ScalarSurfaceFormulation::ScalarSurfaceFormulation;
  void check() const override;
  Eigen::VectorXd load(const WorkShare& share) const override;
  SplitMatrix matrix(const std::vector<FormTerm>& terms) const override;
  Constraints constraints() const override;
  Messages messages() const override;

 private:
  /// The boundary edges by condition, each list in the order of the space's "all": u on every
  /// edge (essential.value_edges), ∂_ν u on the clamped ones (essential.normal_edges), Δ_Γu natural
  /// on the simply supported ones. Parts in config order, "all" first, named parts overriding it;
  /// a lifted surface without problem.boundary is clamped everywhere.
  struct Parts {
    EssentialBoundary essential;
    std::vector<BoundaryEdge> simply_supported;
  };
  Parts parts() const;
};

}  // namespace iga
