#include "assembly/surface_calculus.hpp"

#include <Eigen/LU>

#include <algorithm>

#include "spaces/surface_values.hpp"

namespace iga {

double surface_laplacian_of_ambient(const Eigen::Matrix3d& D, const Eigen::Vector3d& g, const Eigen::Vector3d& n,
                                    double H) {
  return D.trace() - n.dot(D * n) - H * g.dot(n);
}

Eigen::Matrix3d covariant_hessian_of_ambient(const Eigen::Matrix3d& D, const Eigen::Vector3d& g,
                                             const Eigen::Vector3d& n, const Eigen::Matrix3d& W) {
  const Eigen::Matrix3d P = Eigen::Matrix3d::Identity() - n * n.transpose();
  return P * D * P - g.dot(n) * W;
}

void ShapeOperatorByDifferences::compute(Space::Evaluator& evaluator, int element, const QuadratureRule& rule,
                                         bool triangle, const std::vector<Eigen::Matrix<double, 3, 2>>& jacobian3,
                                         std::vector<Eigen::Matrix3d>& W) {
  // Sixth-order central differences f' ≈ Σ_m c_m (f(p + mδ) − f(p − mδ)) / δ, m = 1, 2, 3.
  constexpr double c[3] = {3.0 / 4, -3.0 / 20, 1.0 / 60};
  constexpr int per_point = 12;  // 2 directions × 3 distances × 2 signs
  const int q = rule.size();
  if (base_ != rule.points || triangle_ != triangle) {
    base_ = rule.points;
    triangle_ = triangle;
    shifted_.points.resize(per_point * q);
    shifted_.weights.assign(per_point * q, 0.0);
    delta_.resize(q);
    for (int k = 0; k < q; ++k) {
      // The shifted points stay inside the reference cell (evaluators may refuse points outside).
      const Point2& p0 = rule.points[k];
      const double margin = triangle ? std::min({p0.x(), p0.y(), 1 - p0.x() - p0.y()})
                                     : std::min({p0.x(), 1 - p0.x(), p0.y(), 1 - p0.y()});
      delta_[k] = std::min(2.5e-4, margin / 4);
      for (int a = 0; a < 2; ++a)
        for (int m = 0; m < 3; ++m)
          for (int sign = 0; sign < 2; ++sign) {
            Point2 p = p0;
            p(a) += (sign == 0 ? 1 : -1) * (m + 1) * delta_[k];
            shifted_.points[per_point * k + 6 * a + 2 * m + sign] = p;
          }
    }
  }
  evaluator.evaluate_geometry(element, shifted_, geometry_);
  W.resize(q);
  for (int k = 0; k < q; ++k) {
    Eigen::Matrix<double, 3, 2> dn = Eigen::Matrix<double, 3, 2>::Zero();
    for (int a = 0; a < 2; ++a)
      for (int m = 0; m < 3; ++m) {
        const int i = per_point * k + 6 * a + 2 * m;
        dn.col(a) += c[m] * (surface_normal(geometry_.jacobian3[i]) - surface_normal(geometry_.jacobian3[i + 1]));
      }
    dn /= delta_[k];
    const Eigen::Matrix<double, 3, 2>& J = jacobian3[k];
    const Eigen::Matrix2d G = J.transpose() * J;
    const Eigen::Matrix3d w = dn * G.inverse() * J.transpose();
    W[k] = 0.5 * (w + w.transpose());  // symmetric exactly; the differences only to O(δ⁶)
  }
}

}  // namespace iga
