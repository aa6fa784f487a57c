#pragma once
/// @file
/// The rotation of a Kirchhoff–Love shell held on boundary edges (clamped edges, symmetry planes),
/// by Nitsche's method (docs/shells.md, "Clamped edges"). The rotation about the edge is
/// θ(u) = n·∂_ν u (ν the outward conormal); its work-conjugate in the bending energy is the
/// bending moment M_νν(u) = ν·m(u)·ν, m = D[(1−ν_P) κ + ν_P tr κ P], κ(u) = Σ_i n_i ∇_Γ∇_Γu_i
/// (shell_integrators.hpp). Integrating the bending energy by parts leaves ∫_E M_νν(u) θ(v) on the
/// boundary, so the consistent, symmetric form that holds θ = 0 weakly is
///   − ∫_E M_νν(u) θ(v) + M_νν(v) θ(u) ds + (η D / h_E) ∫_E θ(u) θ(v) ds,
/// added to the stiffness; coercive for η above a constant of the inverse inequality (η is the
/// caller's: ShellFormulation uses 10 (p + 1)²).

#include <vector>

#include "assembly/shell_integrators.hpp"
#include "assembly/sparsity.hpp"
#include "spaces/space.hpp"

namespace iga {

/// The Nitsche terms above on one edge: `local` (3m × 3m, m the functions of the edge's element,
/// rows in blocks: the m functions for x, then y, then z) and `dofs` their unknowns in the block
/// numbering below. For backends that assemble element by element (the PETSc distribution).
void shell_rotation_edge_matrix(const Space& space, const BoundaryEdge& edge, const ShellMaterial& material, double eta,
                                int quadrature_degree, Space::Evaluator& evaluator, Eigen::MatrixXd& local,
                                std::vector<int>& dofs);

/// The Nitsche terms above on `edges`, a 3N × 3N matrix in the shell's block numbering
/// (component c of function i at c·N + i).
SparseMatrix shell_rotation_nitsche(const Space& space, const std::vector<BoundaryEdge>& edges,
                                    const ShellMaterial& material, double eta, int quadrature_degree);

}  // namespace iga
