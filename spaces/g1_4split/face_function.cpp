#include "spaces/g1_4split/face_function.hpp"

#include <Eigen/LU>

namespace iga {

void tensor_tables(const SplitBSpline& b, const std::vector<Point2>& points, Eigen::MatrixXd (&tables)[6]) {
  const int n = b.size(), q = static_cast<int>(points.size());
  for (auto& t : tables) t.resize(n * n, q);
  for (int p = 0; p < q; ++p) {
    const Eigen::MatrixXd U = b.derivatives(points[p].x(), 2), V = b.derivatives(points[p].y(), 2);
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const int l = i + j * n;
        tables[0](l, p) = U(0, i) * V(0, j);
        tables[1](l, p) = U(1, i) * V(0, j);
        tables[2](l, p) = U(0, i) * V(1, j);
        tables[3](l, p) = U(2, i) * V(0, j);
        tables[4](l, p) = U(1, i) * V(1, j);
        tables[5](l, p) = U(0, i) * V(2, j);
      }
  }
}

Eigen::Matrix<double, 6, 1> face_jet(const SplitBSpline& b, const Eigen::VectorXd& c, const Point2& uv) {
  const int n = b.size();
  const Eigen::MatrixXd U = b.derivatives(uv.x(), 2), V = b.derivatives(uv.y(), 2);
  const Eigen::Map<const Eigen::MatrixXd> C(c.data(), n, n);  // C(i, j) = b_{i,j}
  const Eigen::MatrixXd CV = C * V.transpose();                // n x 3
  Eigen::Matrix<double, 6, 1> out;
  out << U.row(0).dot(CV.col(0)), U.row(1).dot(CV.col(0)), U.row(0).dot(CV.col(1)), U.row(2).dot(CV.col(0)),
      U.row(1).dot(CV.col(1)), U.row(0).dot(CV.col(2));
  return out;
}

Eigen::MatrixXd piece_bernstein(const SplitBSpline& b, const Eigen::VectorXd& c, int hu, int hv) {
  const int n = b.size();
  const Eigen::Map<const Eigen::MatrixXd> C(c.data(), n, n);
  return b.bernstein_extraction(hu) * C * b.bernstein_extraction(hv).transpose();
}

Eigen::VectorXd interpolate_face(const SplitBSpline& b, const std::vector<double>& values) {
  const int n = b.size();
  const Eigen::VectorXd g = b.greville();
  Eigen::MatrixXd A(n, n);  // A(p, i) = N_i(g_p)
  for (int p = 0; p < n; ++p) A.row(p) = b.derivatives(g(p), 0).row(0);
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(A);
  // values(p + q n) = f(g_p, g_q) = sum_ij N_i(g_p) b_ij N_j(g_q): C = A^{-1} F A^{-T}.
  const Eigen::Map<const Eigen::MatrixXd> F(values.data(), n, n);
  const Eigen::MatrixXd X = lu.solve(F);
  const Eigen::MatrixXd C = lu.solve(X.transpose()).transpose();
  return Eigen::Map<const Eigen::VectorXd>(C.data(), n * n);
}

}  // namespace iga
