#include "assembly/error_indicator.hpp"

#include <Eigen/LU>
#include <cmath>
#include <stdexcept>

namespace iga {

std::vector<double> poisson_residual_indicators(const Space& space, const Eigen::VectorXd& coefficients,
                                                const ScalarField& source, int quadrature_degree) {
  if (coefficients.size() != space.dimension())
    throw std::invalid_argument("poisson_residual_indicators: one coefficient per basis function expected");
  const int ne = space.num_elements();
  std::vector<double> eta(ne, 0.0);
#pragma omp parallel
  {
    std::unique_ptr<Space::Evaluator> evaluator = space.make_evaluator();
    PointValues v;
#pragma omp for schedule(dynamic, 16)
    for (int e = 0; e < ne; ++e) {
      const RulePtr rule = space.quadrature(e, quadrature_degree);
      evaluator->evaluate(e, *rule, update_values | update_gradients | update_hessians, v);
      double area = 0.0, residual2 = 0.0;
      for (int q = 0; q < v.num_points(); ++q) {
        double laplacian = 0.0;
        for (int i = 0; i < v.num_functions(); ++i) laplacian += coefficients[v.dofs[i]] * (v.dxx(i, q) + v.dyy(i, q));
        const double w = rule->weights[q] * std::abs(v.jacobian[q].determinant());
        const double r = source(Point2(v.x.col(q))) + laplacian;
        area += w;
        residual2 += w * r * r;
      }
      eta[e] = std::sqrt(area) * std::sqrt(residual2);
    }
  }
  return eta;
}

double total_indicator(const std::vector<double>& eta) {
  double s = 0.0;
  for (double x : eta) s += x * x;
  return std::sqrt(s);
}

}  // namespace iga
