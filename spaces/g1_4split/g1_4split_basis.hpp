#pragma once
/// @file
/// The local basis of the 4-split G1 space (vertex, edge and face functions): a sparse matrix whose
/// columns are the basis functions as broken coefficient vectors (face f's B-spline coefficient
/// b_{i,j} at row f (m+1)² + i + j (m+1)). Construction is local: per vertex a small nullspace (the
/// admissible corner data H(γ)) lifted along every interior edge at the vertex; per interior edge
/// the nullspace of its equations on the strips; per boundary edge and face single coefficients.

#include <Eigen/Sparse>
#include <stdexcept>
#include <vector>

#include "spaces/g1_4split/g14_local_problems.hpp"
#include "spaces/g1_4split/gluing.hpp"
#include "spaces/g1_4split/quad_topology.hpp"
#include "spaces/g1_4split/split_bspline.hpp"

namespace iga {

/// Thrown when a vertex datum cannot be lifted along an edge: the edge is not separable at this degree.
class NotSeparable : public std::runtime_error {
 public:
  NotSeparable(int edge, int vertex, const std::string& what) : std::runtime_error(what), edge(edge), vertex(vertex) {}
  int edge, vertex;
};

struct G14Basis {
  SplitBSpline bspline{3, 1};
  /// broken size x dimension; columns: vertex functions, then edge functions, then face functions.
  Eigen::SparseMatrix<double> functions;
  /// Each vertex's and edge's range of columns.
  G14Numbering numbering;
  /// Per face: the functions of its vertices, edges and its own (G14Numbering::face_functions,
  /// sorted; every one non-zero on it on the meshes tested) and their coefficients there,
  /// (m+1)² x face_dofs[f].size().
  std::vector<std::vector<int>> face_dofs;
  std::vector<Eigen::SparseMatrix<double>> extraction;
  int dimension() const { return static_cast<int>(functions.cols()); }
};

/// The symmetric gluing value A of every vertex: 2cos(2π/F) inside, 2cos(α/F) on the boundary
/// (α from `boundary_angles`, or π when it is empty), snapped to 0 at crossing vertices.
std::vector<double> symmetric_vertex_values(const QuadTopology& t, const std::vector<double>& boundary_angles = {});

/// Gluing data per edge (unused entries for boundary edges): the symmetric data of the mesh,
/// a(t) = A_{g0} d0(t) - A_{g1} d0(1 - t) with vertex_gluing_value. `boundary_angles` (empty, or
/// one per vertex) gives the interior angle α of the domain at boundary vertices, A = 2cos(α/F);
/// empty means a straight boundary (α = π) everywhere. Blending::lines: line_gluing of these values.
std::vector<SplitGluing> symmetric_gluing(const QuadTopology& t, Blending blending,
                                          const std::vector<double>& boundary_angles = {});

/// The gluing of a refined mesh inherited from the coarse one (nested spaces): halves of a coarse
/// edge restrict its a(t), edges inside a coarse face get a ≡ 0. `fine` = coarse.refined().
std::vector<SplitGluing> inherited_gluing(const QuadTopology& coarse, const std::vector<SplitGluing>& gluing,
                                         const QuadTopology& fine);

/// Build the local basis for degree k, regularity r. Throws NotSeparable when some vertex datum
/// cannot be lifted along an edge (k below the edge's separability degree).
G14Basis build_g14_basis(const QuadTopology& t, const std::vector<SplitGluing>& gluing, int k, int r);

/// All C0 + G1 equations of all interior edges (rows) on the broken coefficients (columns).
Eigen::SparseMatrix<double> global_constraints(const QuadTopology& t, const std::vector<SplitGluing>& gluing,
                                               const SplitBSpline& b);

/// The dimension formula of the paper, extended to boundaries: Σ_int (d_τ - 9) + (4k-2r-6) E_bd +
/// 3V + 4F + V₊ + (2k-r-3)² F, with d_τ = dim of the edge syzygies computed as the nullspace of the
/// edge's own equations minus 1, and V₊ the interior vertices whose edges all have a = 0 there.
int g14_dimension_formula(const QuadTopology& t, const std::vector<SplitGluing>& gluing, int k, int r);

/// Number of columns of a numerical nullspace of a dense matrix (singular values below
/// 1e-10 of the largest count as zero).
int nullspace_dimension(const Eigen::MatrixXd& M);

}  // namespace iga
