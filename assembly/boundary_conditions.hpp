#pragma once
/// @file
/// Essential boundary conditions for any space, through the Space interface only.
///
/// Method (chosen so that optimal rates hold for every space, including Hermite-type and G1 ones
/// whose boundary functions are not interpolatory):
///  1. The *constrained* global functions are those whose trace on an edge with value data, or
///     whose normal derivative on an edge with normal-derivative data, is not identically zero
///     (detected at the points of an edge rule with more points than the trace's degree).
///  2. Their coefficients minimise  Σ_value-edges ∫ (u_h − g)² ds + Σ_normal-edges h_E² ∫ (∂u_h/∂n − g_n)² ds
///     over the constrained functions (all others held at zero): a boundary L2 projection. The h_E²
///     weight makes both terms scale alike, so both data are matched to optimal order.
///  3. The constrained coefficients are fixed and eliminated: A_ff u_f = b_f − A_fc u_c. The
///     right-hand side and every refinement residual are evaluated on the whole system,
///     b − A (u_c + u_f), in long double with A kept in extended precision (SplitMatrix): A_fc u_c
///     cancels to O(h²) from O(h⁻²) terms for the biharmonic problem, and a residual that forgot
///     A's own rounding would leave an error floor growing like h⁻⁴.
/// The projection matrix is SPD when the boundary traces of those functions are linearly
/// independent. When they are not (e.g. vertex functions of G1 spaces where boundary parts with
/// different conditions meet), a column-pivoted QR picks an independent subset to constrain, and each
/// dependent function stays free after subtracting its trace's combination of the others (a local
/// change of basis, recorded in Constraints::basis_change).

#include <Eigen/Core>
#include <vector>

#include "assembly/fields.hpp"
#include "assembly/sparsity.hpp"
#include "assembly/split_matrix.hpp"

namespace iga {

/// Where essential data are imposed.
struct EssentialBoundary {
  std::vector<BoundaryEdge> value_edges;   ///< u = g        (dirichlet, clamped, simply supported)
  std::vector<BoundaryEdge> normal_edges;  ///< ∂u/∂n = g_n  (clamped)
  bool empty() const { return value_edges.empty() && normal_edges.empty(); }
};

/// Coefficients fixed by essential data, and the rest.
struct Constraints {
  std::vector<int> constrained;  ///< sorted global indices
  std::vector<int> free;         ///< sorted global indices
  Eigen::VectorXd values;        ///< length dimension; the fixed values at constrained indices, 0 elsewhere
  /// Usually empty. Where the boundary traces of the functions seen by the data are linearly
  /// dependent, a dependent one, φ_k, stays free as φ_k − Σ_j α_j φ_j (zero boundary data; the φ_j
  /// constrained): triplet (row j, column = position of k in `free`, value −α_j).
  std::vector<Eigen::Triplet<double>> basis_change;
};

/// No function constrained: every index of a space of dimension `n` free, the values zero.
Constraints all_free(int n);

/// Find the constrained functions and their values by the boundary projection above.
/// `g` gives u on value edges, `g_n` gives ∂u/∂n on normal edges (may be empty when there are none).
Constraints impose_essential(const Space& space, const EssentialBoundary& boundary, const BoundaryField& g,
                             const BoundaryField& g_n, int quad_degree);

/// The system on the free coefficients: A_ff (from A.high) and b_f − A_fc u_c (reduced_residual at 0).
void reduce_system(const SplitMatrix& A, const Eigen::VectorXd& b, const Constraints& c, SparseMatrix& A_free,
                   Eigen::VectorXd& b_free);
/// The same for a matrix known only in double.
void reduce_system(const SparseMatrix& A, const Eigen::VectorXd& b, const Constraints& c, SparseMatrix& A_free,
                   Eigen::VectorXd& b_free);

/// The residual of the reduced system for the free coefficients u_free, computed on the whole
/// system: the free rows (Tᵀ with a basis change) of b − A (values + T u_free), accumulated in
/// long double with A = high + low, rounded once.
Eigen::VectorXd reduced_residual(const SplitMatrix& A, const Eigen::VectorXd& b, const Constraints& c,
                                 const Eigen::VectorXd& u_free);

/// The free unknowns in terms of the global functions, u = values + T u_free: T (dimension x
/// free) has identity columns, plus the basis change of dependent boundary functions. Row i lists
/// the unknowns function i depends on (how the PETSc backend maps an element's functions).
Eigen::SparseMatrix<double, Eigen::RowMajor> free_basis(const Constraints& c);

/// The full coefficient vector from the free solution and the fixed values.
Eigen::VectorXd expand_solution(const Eigen::VectorXd& u_free, const Constraints& c);

}  // namespace iga
