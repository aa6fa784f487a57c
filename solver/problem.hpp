#pragma once
/// @file
/// The boundary value problem of a config: PDE, bilinear form (as integrator terms), source,
/// boundary parts with their kinds, and the data on them. With `exact` given, every datum is derived from it symbolically.

#include <optional>
#include <string>
#include <vector>

#include "assembly/fields.hpp"
#include "assembly/integrators.hpp"
#include "config/config_node.hpp"
#include "config/expression.hpp"
#include "solver/eigen_spec.hpp"
#include "solver/shell_spec.hpp"

namespace iga {

/// laplace_beltrami: −Δ_Γu + c u = f on a surface in 3D; surface_biharmonic: Δ_Γ²u + c u = f on a
/// closed surface in 3D (both solver/surface_problem.hpp); kirchhoff_love_shell: the linear
/// Kirchhoff–Love shell, a displacement with three components (solver/shell_problem.hpp).
enum class Pde { poisson, biharmonic, laplace_beltrami, surface_biharmonic, kirchhoff_love_shell };
/// The problems posed on a surface in 3D (space with ambient_dimension() == 3).
inline bool on_surface(Pde pde) {
  return pde == Pde::laplace_beltrami || pde == Pde::surface_biharmonic || pde == Pde::kirchhoff_love_shell;
}
enum class BoundaryKind { dirichlet, neumann, clamped, simply_supported };

std::string to_string(Pde pde);
std::string to_string(BoundaryKind kind);

/// A named boundary part ("all", "left", ...) and the condition imposed there.
struct BoundaryPart {
  std::string name;
  BoundaryKind kind;
  std::string where;  ///< config location, for messages about unknown part names
};

struct ProblemSpec {
  Pde pde = Pde::poisson;
  /// The bilinear form as Σ coefficient · integrator (assembly/integrators.hpp): ∫ ∇u·∇v for
  /// Poisson, ∫ Δu Δv or ∫ D²u : D²v (problem.form) for plates, ∫ ∇_Γu·∇_Γv + c ∫ u v on surfaces.
  /// A new operator is a new integrator here, not a new case of the solver.
  std::vector<FormTerm> terms{stiffness_integrator()};
  std::optional<SymbolicFunction> exact;
  SymbolicFunction source = SymbolicFunction::constant(0.0);
  std::vector<BoundaryPart> boundary;  ///< in config order; "all" first applies, later parts override

  // Boundary data (from `exact`, or from `data:`; zero when neither gives them).
  SymbolicFunction value = SymbolicFunction::constant(0.0);      ///< u on dirichlet/clamped/simply supported parts
  std::optional<SymbolicFunction> gradient_x, gradient_y;        ///< ∇u, when known (∂u/∂n = ∇u·n)
  SymbolicFunction normal_derivative = SymbolicFunction::constant(0.0);  ///< ∂u/∂n when ∇u is not known
  SymbolicFunction laplacian = SymbolicFunction::constant(0.0);  ///< Δu on simply supported parts

  /// Config places the source and the boundary data came from ("FILE:LINE:COL: problem.exact"),
  /// for messages about them found only while solving.
  std::string source_where = "problem.source", data_where = "problem.data";

  /// Surface problems only: the exact solution or the source as functions of x, y, z (the planar
  /// members exact/source then stay unset/zero).
  std::optional<SymbolicFunction> surface_exact, surface_source;
  /// laplace_beltrami on an open surface: u on its boundary curve (boundary: {all: dirichlet};
  /// from boundary_value, else the exact solution).
  std::optional<SymbolicFunction> surface_dirichlet;
  /// Surface problems: c in −Δ_Γu + c u = f or Δ_Γ²u + c u = f (laplace_beltrami with c = 0: the
  /// solution is fixed up to a constant; surface_biharmonic needs c > 0).
  double reaction = 1.0;
  /// An eigenproblem (problem.eigen): the smallest eigenvalues of the operator under homogeneous
  /// essential conditions; no source, no data, no exact solution.
  std::optional<EigenSpec> eigen;
  /// kirchhoff_love_shell: material, load, supports (the members above stay unused).
  std::optional<ShellSpec> shell;

  /// u, ∇u, D²u of the exact solution as callables (empty members when there is none).
  ExactSolution exact_solution() const;
  /// ∂u/∂n as a boundary field (from ∇u when known).
  BoundaryField normal_derivative_field() const;
};

/// A problem with manufactured solution `u`: source and all boundary data derived from it.
/// `boundary` lists parts as in the config ("all" first).
ProblemSpec manufactured_problem(Pde pde, const SymbolicFunction& u, std::vector<BoundaryPart> boundary);

/// Parse and validate the `problem:` section (keys pde, exact, source, boundary, data, form, eigen).
ProblemSpec parse_problem(const ConfigNode& node);

}  // namespace iga
