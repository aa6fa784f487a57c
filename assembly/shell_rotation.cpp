#include "assembly/shell_rotation.hpp"

#include <memory>
#include <stdexcept>

#include "assembly/edge_points.hpp"

namespace iga {

void shell_rotation_edge_matrix(const Space& space, const BoundaryEdge& e, const ShellMaterial& material, double eta,
                                int quadrature_degree, Space::Evaluator& evaluator, Eigen::MatrixXd& local,
                                std::vector<int>& dofs) {
  if (space.ambient_dimension() != 3) throw std::invalid_argument("shell_rotation_nitsche: a space on a surface in 3D");
  const int n = space.dimension();
  const double D = material.bending_stiffness(), nu_p = material.poisson_ratio;
  const QuadratureRule line = gauss_legendre_for_degree(quadrature_degree);
  const unsigned flags = update_values | update_gradients | update_hessians | update_surface_curvature;
  PointValues g;
  const CellShape shape = space.cell_shape(e.element);
  const QuadratureRule rule = points_on_edge(shape, e.local_edge, 0.0, 1.0, line);
  evaluator.evaluate(e.element, rule, flags, g);
  const int m = g.num_functions(), q = rule.size();
  const Point2 t = reference_edge_tangent(shape, e.local_edge);
  Eigen::VectorXd ds(q);
  for (int k = 0; k < q; ++k) ds(k) = line.weights[k] * (g.jacobian3[k] * Eigen::Vector2d(t.x(), t.y())).norm();
  const double gamma = eta * D / ds.sum();
  // Per point: θ and M_νν of the scalar functions, times n_c for component c.
  Eigen::MatrixXd theta(m, q), moment(m, q);
  for (int k = 0; k < q; ++k) {
    const Eigen::Vector3d cn = outward_conormal(g, k, shape, e.local_edge);
    for (int i = 0; i < m; ++i) {
      const Eigen::Matrix3d H = g.hessian(i, k);
      theta(i, k) = g.gradient(i, k).dot(cn);
      moment(i, k) = D * ((1.0 - nu_p) * cn.dot(H * cn) + nu_p * H.trace());
    }
  }
  local.resize(3 * m, 3 * m);
  dofs.resize(3 * m);
  for (int c = 0; c < 3; ++c)
    for (int i = 0; i < m; ++i) dofs[c * m + i] = c * n + g.dofs[i];
  for (int c = 0; c < 3; ++c)
    for (int d = 0; d < 3; ++d)
      for (int i = 0; i < m; ++i)
        for (int j = 0; j < m; ++j) {
          double sum = 0;
          for (int k = 0; k < q; ++k) {
            const double nc = g.normal3(c, k), nd = g.normal3(d, k);
            const double ti = nc * theta(i, k), tj = nd * theta(j, k);
            const double mi = nc * moment(i, k), mj = nd * moment(j, k);
            sum += ds(k) * (-mi * tj - mj * ti + gamma * ti * tj);
          }
          local(c * m + i, d * m + j) = sum;
        }
}

SparseMatrix shell_rotation_nitsche(const Space& space, const std::vector<BoundaryEdge>& edges,
                                    const ShellMaterial& material, double eta, int quadrature_degree) {
  const int n = space.dimension();
  const std::unique_ptr<Space::Evaluator> evaluator = space.make_evaluator();
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::MatrixXd local;
  std::vector<int> dofs;
  for (const BoundaryEdge& e : edges) {
    shell_rotation_edge_matrix(space, e, material, eta, quadrature_degree, *evaluator, local, dofs);
    for (int j = 0; j < local.cols(); ++j)
      for (int i = 0; i < local.rows(); ++i) entries.emplace_back(dofs[i], dofs[j], local(i, j));
  }
  SparseMatrix A(3 * n, 3 * n);
  A.setFromTriplets(entries.begin(), entries.end());
  return A;
}

}  // namespace iga
