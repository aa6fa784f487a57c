#pragma once
/// @file
/// The local-nullspace basis of S¹_k (notes §4.5) on a PatchMesh (bilinear quads and affine
/// triangles) with geometry-derived gluing data:
/// face functions (interior Bernstein coefficients), edge functions (null space of the edge's C0 and
/// G1 rows on rows 0–1 along the edge minus the corner sets), vertex functions (null space of the
/// rows of the vertex's edges on rows 0–1 along its edges minus the other corners, reduced to a
/// complement of the edge functions with independent corner data: a value function with all
/// corner coefficients 1, the others with corner data orthogonal to it).
///
/// Every construction step is a small dense problem per entity: work linear in the number of faces.

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

#include "spaces/g1/edge_rows.hpp"
#include "spaces/g1/gluing_data.hpp"
#include "spaces/g1/patch_mesh.hpp"

namespace iga {

enum class G1Entity { vertex, edge, face };

struct G1FunctionInfo {
  G1Entity entity;
  int id;                       ///< vertex, edge or face index
  bool value_function = false;  ///< the vertex function with all corner coefficients 1
};

/// The basis: global functions as Bernstein coefficients per face.
struct G1Basis {
  int degree = 0;
  std::vector<G1FunctionInfo> info;                      ///< per global function
  std::vector<std::vector<int>> face_dofs;               ///< per face: sorted active global functions
  std::vector<Eigen::SparseMatrix<double>> extraction;   ///< per face: bernstein_count x face_dofs.size()
  int dimension() const { return static_cast<int>(info.size()); }
};

/// Thrown when a local problem has fewer functions than the theory predicts (k below the
/// separability degree of some edge, notes §2.5 and §4.5).
struct IncompleteBasis : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Build the basis of degree k (complete from 4 on, depending on the mesh). Throws IncompleteBasis
/// when k is too low for the local construction or a local count disagrees.
G1Basis build_g1_basis(const PatchMesh& mesh, const std::vector<EdgeGluing>& gluing, int k);

/// dim H(γ) of Prop. 5.1: 3 + F − Σ c_τ(γ) + c₊(γ) (number of vertex functions at v).
int vertex_function_count(const PatchMesh& mesh, const std::vector<EdgeGluing>& gluing, int v);

/// Theorem 6.3: the dimension of S¹_k for k >= s*, from d_τ(k) of every edge (quads and triangles).
int theorem_dimension(const PatchMesh& mesh, const std::vector<EdgeGluing>& gluing, int k);

}  // namespace iga
