#include "spaces/g1/gradient_jump.hpp"

#include <algorithm>
#include <Eigen/Dense>

#include "spaces/g1/bernstein_face.hpp"

namespace iga {

int gradient_jump_samples(int k) { return 2 * k + 4; }

namespace {

/// Physical gradient at reference point uv of face f with Bernstein coefficients c.
Eigen::Vector2d physical_gradient(const PatchMesh& mesh, int k, int f, const Eigen::VectorXd& c, const Point2& uv) {
  const Eigen::MatrixXd jet = bernstein_jet(mesh.shape(f), k, uv);
  const Eigen::Vector2d ref(jet.row(1).dot(c), jet.row(2).dot(c));
  const Eigen::Matrix2d j = mesh.map(f, uv).jacobian;
  return j.transpose().partialPivLu().solve(ref);  // ∇̂u = Jᵀ ∇u
}

}  // namespace

double max_gradient_jump(const PatchMesh& mesh, int k, const std::vector<Eigen::VectorXd>& face_coefficients) {
  const int n = gradient_jump_samples(k);
  double jump = 0.0;
  for (int e = 0; e < mesh.num_edges(); ++e) {
    const MeshEdge& edge = mesh.edge(e);
    if (edge.boundary()) continue;
    const int f1 = edge.first.face, f2 = edge.second.face;
    for (int s = 0; s < n; ++s) {
      const double t = static_cast<double>(s) / (n - 1);
      // `second` traverses the edge in the opposite direction: parameter 1 - t is the same point.
      const Point2 uv1 = reference_edge_point(mesh.shape(f1), edge.first.local_edge, t);
      const Point2 uv2 = reference_edge_point(mesh.shape(f2), edge.second.local_edge, 1.0 - t);
      const Eigen::Vector2d g1 = physical_gradient(mesh, k, f1, face_coefficients[f1], uv1);
      const Eigen::Vector2d g2 = physical_gradient(mesh, k, f2, face_coefficients[f2], uv2);
      jump = std::max(jump, (g1 - g2).norm());
    }
  }
  return jump;
}

}  // namespace iga
