#pragma once
/// @file
/// Hermite degrees of freedom and per-cell Bézier extraction for C^r generalized splines over an
/// admissible T-mesh (notes §2.5, §3.5). Cells may carry different section spaces of one n; edges
/// between them have d_e = 0 (d_e = 1 needs exponential families, not provided). Needs n >= 2r+1,
/// and n >= 2r+3 when some edge has d_e = 0.
///
/// DOFs (numbered by hermite_dofs.hpp), in this order:
///  - (V) every non-T-junction vertex w: D_s^a D_t^b p(w), a, b <= r, numbered a + b (r+1);
///  - (E) every composite edge e (lo end w_a): the (r+1) (n-2r-3+d_e) one-sided tangential
///    derivatives of the traces, L^i D_tan^i D_nor^b p(w_a) for r < i <= n-r-3+d_e, b <= r (L = |e|);
///  - (C) every cell: its interior Bernstein coefficients c_ij, r < i, j < n-r.
/// Traces along a composite edge are one section-space function over the whole edge (Lemma 2),
/// which gives the jets at its T-junctions; edges are processed in the mesh's dependency order.

#include <Eigen/Core>
#include <vector>

#include "spaces/tmesh/tmesh.hpp"

namespace iga {

/// Result of the extraction.
struct HermiteExtraction {
  int dimension = 0;
  /// Per cell: global indices of the functions active on it (sorted) and the matrix E with
  /// Bernstein coefficient c_loc = sum_a E(a, loc) U[dofs[a]], loc = i + j (n+1); n_active x (n+1)^2.
  std::vector<std::vector<int>> dofs;
  std::vector<Eigen::MatrixXd> matrix;
  /// Largest disagreement between the two sides that both determine a corner coefficient
  /// (a free self-check: round-off when the construction is consistent).
  double corner_mismatch = 0.0;
};

/// Build the extraction for C^r on `mesh`. Throws std::invalid_argument when the mesh is not
/// admissible (reason included), the section spaces differ in n, an edge has d_e = 1, or n is too small.
HermiteExtraction hermite_extraction(const TMesh& mesh, int r);

}  // namespace iga
