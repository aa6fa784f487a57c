#pragma once
/// @file
/// The local problems of the 4-split G1 basis (g1_4split_basis.hpp), one entity at a time: an
/// interior edge's equations with its strip solver, a vertex's admissible corner data lifted along
/// its interior edges, an edge's strip solutions, a face's interior coefficients. The whole basis
/// solves them all in this order; a rank's part (G14Space::build_on) solves those of the entities
/// at its faces, and a skeleton only counts each entity's functions (the numbering) and checks
/// that every vertex datum lifts, with no more than one vertex's problems alive at a time.

#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <functional>
#include <map>
#include <vector>

#include "spaces/g1_4split/gluing.hpp"
#include "spaces/g1_4split/quad_topology.hpp"
#include "spaces/g1_4split/split_bspline.hpp"

namespace iga {

class NotSeparable;

/// One basis function as broken coefficients (index f (m+1)² + i → value), before round-off
/// entries are dropped (kept_entries).
using BrokenFunction = std::map<int, double>;

/// Interior edge e's equations split into the corner columns at each end and the strip.
struct G14EdgeSystem {
  Eigen::MatrixXd M;               ///< all equations over `columns`
  std::vector<int> columns;        ///< global broken indices
  std::vector<int> strip;          ///< positions (in columns) of the strip unknowns
  std::vector<int> end_corner[2];  ///< positions of the corner unknowns at g0 / g1
  Eigen::MatrixXd M_strip;
  Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> solver;
};

/// How many functions each vertex and edge has (and each face: the same count): the numbering,
/// columns vertex by vertex, then edge by edge, then face by face.
struct G14Numbering {
  std::vector<int> vertex_first;  ///< V + 1 entries: vertex v's functions are [vertex_first[v], vertex_first[v+1])
  std::vector<int> edge_first;    ///< E + 1 entries, after the vertices'
  int per_face = 0;               ///< face f's: edge_first.back() + f per_face, per_face of them
  int dimension(int faces) const { return edge_first.empty() ? 0 : edge_first.back() + faces * per_face; }
  /// The functions of face f's vertices, edges and its own, increasing: every function that can be
  /// non-zero on f (a vertex's functions live on the faces at it, an edge's on its faces).
  void face_functions(const QuadTopology& t, int f, std::vector<int>& out) const;
};

/// The per-face extractions of some faces from basis functions given entry by entry (broken index
/// f (m+1)² + i, column c): each entry on a listed face goes to column "position of c in the face's
/// functions" (G14Numbering::face_functions) of that face's matrix. Shared by the whole basis and a
/// rank's part, so that both give the same matrices.
class G14FaceExtractions {
 public:
  /// `slot[f]`: face f's position among the listed faces, or −1; `face_functions[s]` the
  /// functions of listed face s (increasing).
  G14FaceExtractions(int face_size, const std::vector<int>& slot, std::vector<std::vector<int>> face_functions);
  void add(int column, int index, double value);
  std::vector<Eigen::SparseMatrix<double>> finish() const;
  const std::vector<std::vector<int>>& face_functions() const { return dofs_; }

 private:
  int fs_;
  const std::vector<int>& slot_;
  std::vector<std::vector<int>> dofs_;
  std::vector<std::vector<Eigen::Triplet<double>>> trip_;
};

class G14LocalProblems {
 public:
  /// Gives the system of an interior edge (computed or kept by the caller).
  using SystemOf = std::function<const G14EdgeSystem&(int edge)>;

  G14LocalProblems(const QuadTopology& t, const std::vector<SplitGluing>& gluing, const SplitBSpline& b)
      : t_(t), gluing_(gluing), b_(b) {}

  G14EdgeSystem edge_system(int e) const;
  /// Vertex v's functions (its admissible corner data lifted along each interior edge at v, then
  /// orthonormalised). Throws NotSeparable when a datum does not lift.
  std::vector<BrokenFunction> vertex_functions(int v, const SystemOf& system) const;
  /// Edge e's functions: strip solutions with zero corner data (`system` null for a boundary edge).
  std::vector<BrokenFunction> edge_functions(int e, const G14EdgeSystem* system) const;
  /// Face f's functions: its interior coefficients.
  std::vector<BrokenFunction> face_functions(int f) const;
  int face_count() const;

  /// Solve every local problem once, for the numbering and the errors only: the count of each
  /// vertex's and edge's functions (built and dropped). Each vertex's edge systems are computed
  /// again (never all of them at once).
  G14Numbering count_functions() const;

 private:
  /// The admissible corner data at v (columns) over the corner indices `vc`.
  Eigen::MatrixXd corner_data(int v, std::vector<int>& vc) const;
  /// The lifts of the corner data H over vc along v's interior edges.
  std::vector<BrokenFunction> lifted(int v, const std::vector<int>& vc, const Eigen::MatrixXd& H,
                                     const SystemOf& system) const;
  /// The strip coefficients of edge e's system that lift column h of the corner data H (over the
  /// corner indices with positions `pos`) from v's end; throws NotSeparable when none does.
  Eigen::VectorXd lift_along(int v, int e, const G14EdgeSystem& s, const Eigen::MatrixXd& H, int h,
                             const std::map<int, int>& pos) const;
  /// The error of a vertex datum that does not lift along edge e.
  NotSeparable not_separable(int v, int e, double residual) const;
  const QuadTopology& t_;
  const std::vector<SplitGluing>& gluing_;
  const SplitBSpline& b_;
};

/// The entries of `fn` the basis keeps: those above 1e-14 of its largest (round-off dropped).
std::vector<std::pair<int, double>> kept_entries(const BrokenFunction& fn);

/// Orthonormal basis of the numerical nullspace of M (columns; singular values below 1e-10 of the
/// largest count as zero).
Eigen::MatrixXd numerical_nullspace(const Eigen::MatrixXd& M);

}  // namespace iga
