#pragma once
/// @file
/// The Laplace–Beltrami problem −Δ_Γu + c u = f (c = `reaction`, default 1) on a surface Γ in 3D,
/// solved on a space with ambient_dimension() == 3: closed surfaces, or open ones with u = g on
/// the whole boundary curve (a boundary L2 projection, assembly/surface_dirichlet.hpp). With an exact solution u given in x, y, z, the source is computed at
/// every quadrature point from the surface's own unit normal n and mean curvature H = div_Γ n:
///   Δ_Γu = Δu − nᵀ(∇²u)n − H ∂_n u,
/// so the surface is the exact geometry of the problem (no geometric error). With c = 0 the solution
/// is unique up to a constant: zero mean, or the exact solution's mean when one is given.

#include "assembly/fields.hpp"
#include "config/config_node.hpp"
#include "solver/solve_problem.hpp"

namespace iga {

/// u and its ambient gradient as callables (empty when the problem has no exact solution).
SurfaceExactSolution surface_exact_solution(const ProblemSpec& problem);

/// The given source, else f(x, n, H) = −Δ_Γu + u from the exact solution.
SurfaceSource surface_source(const ProblemSpec& problem);

/// Assemble the Laplace–Beltrami and mass matrices, the load, solve, and measure the errors.
DiscreteSolution solve_surface_problem(const Space& space, const ProblemSpec& problem, SolverKind solver,
                                       const ProgressSink& progress = {});

}  // namespace iga
