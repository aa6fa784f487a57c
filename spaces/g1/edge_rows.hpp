#pragma once
/// @file
/// The C0 and G1 rows of an interior edge (notes §1.4/§1.5) as sparse rows on the Bernstein
/// coefficients of its two faces, and the Bernstein jets they are built from. The jets at the
/// collocation points depend only on the face shape, the local edge and the direction the edge is
/// traversed, not on the face: EdgeCollocation computes them once per degree for every edge.

#include <Eigen/Core>
#include <array>
#include <vector>

#include "quadrature/quadrature_rule.hpp"
#include "spaces/g1/gluing_data.hpp"
#include "spaces/g1/patch_mesh.hpp"

namespace iga {

/// One coefficient of a global function: local Bernstein index `index` of face `face`.
struct FaceCoefficient {
  int face;
  int index;
  double value;
};

/// Collocation points of the G1 rows (k+3 Gauss points in t: the residual has degree <= k+2) and
/// the Bernstein jets (bernstein_jet, 3 x bernstein_count) at them for every (shape, local edge,
/// direction): direction 0 runs from corner e to e+1 (the edge's `first` face), 1 from e+1 to e.
struct EdgeCollocation {
  explicit EdgeCollocation(int k);
  int degree;
  QuadratureRule points;
  /// jets[slot(shape, e, reversed)][p]
  std::array<std::vector<Eigen::MatrixXd>, 16> jets;
  static int slot(CellShape shape, int edge, bool reversed) {
    return (shape == CellShape::triangle ? 8 : 0) + 2 * edge + (reversed ? 1 : 0);
  }
};

/// Sparse rows of the C0 and G1 conditions of interior edge `edge` (notes §1.4/§1.5): k+1 trace
/// equalities and k+3 collocations of c ∂_{X→Z1} f1 − a ∂_{X→Y} f1 − b ∂_{X→Z2} f2 (a polynomial of
/// degree k+2, so exact), each row scaled to max-norm 1.
std::vector<std::vector<FaceCoefficient>> edge_constraint_rows(const PatchMesh& mesh, const EdgeGluing& gluing, int k);
/// The same with the jets computed once (`tables.degree` is k).
std::vector<std::vector<FaceCoefficient>> edge_constraint_rows(const PatchMesh& mesh, const EdgeGluing& gluing,
                                                               const EdgeCollocation& tables);

/// Local indices in rows 0-1 along local edge e of a face, without the first `skip_start` and the
/// last `skip_end` coefficients of each row (2 skips a corner set), appended as (face, index).
void add_edge_rows(const PatchMesh& mesh, int k, int face, int e, int skip_start, int skip_end,
                   std::vector<std::pair<int, int>>& out);

}  // namespace iga
