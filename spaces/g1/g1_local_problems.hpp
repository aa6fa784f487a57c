#pragma once
/// @file
/// The local problems of the G1 basis (g1_basis.hpp), one per edge and one per vertex, shared by
/// the whole construction and by the one that solves only those of some faces (g1_numbering.hpp):
/// both call these same functions, so a function comes out bit for bit the same either way.

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <climits>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "spaces/g1/edge_rows.hpp"
#include "spaces/g1/g1_basis.hpp"
#include "spaces/g1/gluing_data.hpp"
#include "spaces/g1/patch_mesh.hpp"

namespace iga {

/// The message of the lowest-numbered entity that failed, whatever the order the threads report
/// in: the same IncompleteBasis whatever the number of threads (nothing may leave an OpenMP
/// region by an exception).
class FirstError {
 public:
  void offer(int index, const std::string& message) {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (index < index_) {
      index_ = index;
      message_ = message;
    }
  }
  void throw_if_any() const {
    if (index_ < INT_MAX) throw IncompleteBasis(message_);
  }

 private:
  std::mutex mutex_;
  int index_ = INT_MAX;
  std::string message_;
};

/// The prefix of a construction error: the mesh and the degree.
inline std::string where_of(const PatchMesh& mesh, int k) {
  return mesh.name() + ", degree " + std::to_string(k) + ": ";
}

/// What one interior edge's local problem gives, kept for the vertex problems at its ends.
/// With E = the edge's C0 + G1 rows restricted to `unknowns` (rows 0–1 along the edge minus both
/// corner sets), E = U S Vᵀ, and A = the rows restricted to the two corner sets at one end:
/// `null` = ker E (the edge functions); per end, `compat` = coker(E)ᵀ A (the conditions on that
/// end's corner data) and `scaled` = S_r⁻¹ U_rᵀ A, so that −V_r (scaled · x) = −E⁺ A x is the
/// minimum-norm rest of a function with corner data x. E⁺ is never formed: its entries are all of
/// size 1/σ_min, and multiplying by it would leave G1 residuals of eps·cond(E) even where the
/// result is O(1); through the factors the error stays relative to the result. The rows are not kept.
struct EdgeLocal {
  struct End {
    std::vector<std::pair<int, int>> corners;  ///< 8 (face, index): both faces' corner sets at this end
    Eigen::MatrixXd compat, scaled;            ///< dim coker x 8, rank x 8
  };
  std::vector<std::pair<int, int>> unknowns;
  Eigen::MatrixXd null, range;  ///< ker E and V_r: |unknowns| x nullity, |unknowns| x rank
  End end[2];                   ///< at X, at Y
};

/// Throws IncompleteBasis when k is below what the local construction needs on any mesh of these
/// face shapes (3; 4 with triangles or quads).
void check_g1_degree(const PatchMesh& mesh, int k);

/// Edge e's local problem into `l`: its unknowns, and for an interior edge the solve and the check
/// of its number of functions against Theorem 6.3's d_τ(k). Returns the error message (`where`
/// first), empty when the edge is complete.
std::string solve_g1_edge(const PatchMesh& mesh, const std::vector<EdgeGluing>& gluing,
                          const EdgeCollocation& collocation, int k, int e, const std::string& where, EdgeLocal& l);

/// The vertex functions of vertex v (value function first); `at[i]` is the local problem of edge
/// fan(v).edge[i] (unused for boundary edges). Throws IncompleteBasis when v's number of functions
/// is not Prop. 5.1's or constants are not locally representable.
std::vector<std::vector<FaceCoefficient>> build_vertex_functions(const PatchMesh& mesh,
                                                                 const std::vector<EdgeGluing>& gluing, int k, int v,
                                                                 const std::vector<const EdgeLocal*>& at,
                                                                 const std::string& where);

/// The function of local coefficients x on unknowns u, without its zero entries, scaled to max-norm 1
/// when `normalize`.
std::vector<FaceCoefficient> to_function(const Eigen::VectorXd& x, const std::vector<std::pair<int, int>>& u,
                                         bool normalize);

/// The functions of edge e from its local problem `l`, in their order: one unit function per
/// unknown on a boundary edge, the null-space columns on an interior one.
std::vector<std::vector<FaceCoefficient>> edge_functions(const PatchMesh& mesh, int e, const EdgeLocal& l);

/// The face functions of face f: one per interior Bernstein coefficient.
std::vector<std::vector<FaceCoefficient>> face_functions(const PatchMesh& mesh, int f, int k);

/// The per-face extraction of some faces (increasing), from the basis functions handed over in
/// increasing global number: each function becomes a column of every listed face it has
/// coefficients on (face_dofs increasing, as the columns).
class FaceExtractionAssembly {
 public:
  explicit FaceExtractionAssembly(std::vector<int> faces);
  void add(int g, const std::vector<FaceCoefficient>& function);
  /// face_dofs and extraction of `basis`, one entry per listed face.
  void finish(const PatchMesh& mesh, int k, G1Basis& basis);

 private:
  std::vector<int> faces_;
  std::vector<std::vector<int>> dofs_;
  std::vector<std::vector<Eigen::Triplet<double>>> triplets_;
};

}  // namespace iga
