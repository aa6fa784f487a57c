#pragma once
/// @file
/// Test tool: the largest jump of the physical gradient of a piecewise polynomial given by its
/// Bernstein coefficients per face of a PatchMesh, independent of any space's evaluator (the
/// spaces' own g1_jump check is spaces/gradient_jump.hpp). Checks that check on G1 spaces, and
/// C0 tents have exact jumps, so the check can fail.

#include <Eigen/Dense>
#include <algorithm>
#include <vector>

#include "spaces/g1/bernstein_face.hpp"
#include "spaces/g1/patch_mesh.hpp"

namespace iga {

/// Samples per edge for degree k: the jump times both Jacobian determinants is a polynomial of
/// degree <= k+2 along an edge, so 2k+4 points (endpoints included) cannot all miss a nonzero jump.
inline int gradient_jump_samples(int k) { return 2 * k + 4; }

namespace patch_gradient_jump_detail {

/// The Bernstein jets at the n samples t_s = s / (n - 1) of every local edge of both cell shapes,
/// computed once: the samples are symmetric (1 - t_s = t_(n-1-s)), so both faces of an edge use them.
struct SampleJets {
  std::vector<Eigen::MatrixXd> jet[2][4];  // [triangle?][local edge][sample]
  SampleJets(int k, int n) {
    for (int tri = 0; tri < 2; ++tri) {
      const CellShape shape = tri ? CellShape::triangle : CellShape::quadrilateral;
      for (int edge = 0; edge < num_edges(shape); ++edge)
        for (int s = 0; s < n; ++s)
          jet[tri][edge].push_back(bernstein_jet(shape, k, reference_edge_point(shape, edge, double(s) / (n - 1))));
    }
  }
  const Eigen::MatrixXd& at(CellShape shape, int edge, int s) const {
    return jet[shape == CellShape::triangle][edge][s];
  }
};

/// Physical gradient at reference point uv of face f with Bernstein coefficients c (jet at uv).
Eigen::Vector2d physical_gradient(const PatchMesh& mesh, const Eigen::MatrixXd& jet, int f, const Eigen::VectorXd& c,
                                  const Point2& uv) {
  const Eigen::Vector2d ref(jet.row(1).dot(c), jet.row(2).dot(c));
  const Eigen::Matrix2d j = mesh.map(f, uv).jacobian;
  return j.transpose().partialPivLu().solve(ref);  // ∇̂u = Jᵀ ∇u
}

}  // namespace patch_gradient_jump_detail

/// max over interior edges and over gradient_jump_samples(k) equispaced points per edge of
/// |∇u_1 − ∇u_2|, u_f the polynomial of degree k on face f (bidegree (k,k) on a quad, total degree
/// k on a triangle) with Bernstein coefficients face_coefficients[f] (bernstein_face.hpp), pushed
/// to physical coordinates through the face's map. 0 for a mesh without interior edges.
inline double max_gradient_jump(const PatchMesh& mesh, int k, const std::vector<Eigen::VectorXd>& face_coefficients) {
  const int n = gradient_jump_samples(k);
  const patch_gradient_jump_detail::SampleJets jets(k, n);
  double jump = 0.0;
  // Every interior edge on its own (the max is exact in any order).
#pragma omp parallel for schedule(dynamic, 64) reduction(max : jump) if (mesh.num_edges() >= 256)
  for (int e = 0; e < mesh.num_edges(); ++e) {
    const MeshEdge& edge = mesh.edge(e);
    if (edge.boundary()) continue;
    const int f1 = edge.first.face, f2 = edge.second.face;
    const CellShape s1 = mesh.shape(f1), s2 = mesh.shape(f2);
    for (int s = 0; s < n; ++s) {
      const double t = static_cast<double>(s) / (n - 1);
      // `second` traverses the edge in the opposite direction: parameter 1 - t is the same point.
      const Point2 uv1 = reference_edge_point(s1, edge.first.local_edge, t);
      const Point2 uv2 = reference_edge_point(s2, edge.second.local_edge, 1.0 - t);
      const Eigen::Vector2d g1 =
          patch_gradient_jump_detail::physical_gradient(mesh, jets.at(s1, edge.first.local_edge, s), f1, face_coefficients[f1], uv1);
      const Eigen::Vector2d g2 =
          patch_gradient_jump_detail::physical_gradient(mesh, jets.at(s2, edge.second.local_edge, n - 1 - s), f2, face_coefficients[f2], uv2);
      jump = std::max(jump, (g1 - g2).norm());
    }
  }
  return jump;
}

}  // namespace iga
