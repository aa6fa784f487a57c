#include "assembly/constant_coefficients.hpp"

#include <Eigen/QR>
#include <stdexcept>
#include <string>
#include <vector>

#include "spaces/element_values.hpp"

namespace iga {

namespace {

/// max over every element and point of |Σ_i k_i N_i − 1|.
double worst_miss(const Space& space, const Eigen::VectorXd& k, int degree) {
  ElementValues ev(space, update_values);
  double worst = 0;
  for (int e = 0; e < space.num_elements(); ++e) {
    ev.reinit(e, *space.quadrature(e, degree));
    const PointValues& v = ev.values();
    Eigen::VectorXd local(v.dofs.size());
    for (std::size_t i = 0; i < v.dofs.size(); ++i) local(i) = k(v.dofs[i]);
    worst = std::max(worst, ((v.value.transpose() * local).array() - 1.0).abs().maxCoeff());
  }
  return worst;
}

}  // namespace

Eigen::VectorXd constant_coefficients(const Space& space) {
  const int n = space.dimension();
  const int degree = 2 * space.degree() + 2;
  const double tolerance = 1e-9;
  Eigen::VectorXd k = Eigen::VectorXd::Ones(n);
  if (worst_miss(space, k, degree) <= tolerance) return k;

  std::vector<char> known(n, 0);
  ElementValues ev(space, update_values);
  for (int e = 0; e < space.num_elements(); ++e) {
    ev.reinit(e, *space.quadrature(e, degree));
    const PointValues& v = ev.values();
    std::vector<int> unknown;  // local indices
    Eigen::VectorXd rhs = Eigen::VectorXd::Ones(ev.num_points());
    for (std::size_t i = 0; i < v.dofs.size(); ++i) {
      if (known[v.dofs[i]]) rhs -= k(v.dofs[i]) * v.value.row(i).transpose();
      else unknown.push_back(static_cast<int>(i));
    }
    if (unknown.empty()) continue;
    Eigen::MatrixXd V(ev.num_points(), unknown.size());
    for (std::size_t j = 0; j < unknown.size(); ++j) V.col(j) = v.value.row(unknown[j]).transpose();
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(V);
    // Linearly dependent on this element: another element fixes them.
    if (qr.rank() < static_cast<int>(unknown.size())) continue;
    const Eigen::VectorXd fit = qr.solve(rhs);
    for (std::size_t j = 0; j < unknown.size(); ++j) {
      k(v.dofs[unknown[j]]) = fit(j);
      known[v.dofs[unknown[j]]] = 1;
    }
  }
  for (int i = 0; i < n; ++i)
    if (!known[i])
      throw std::runtime_error("constant_coefficients: function " + std::to_string(i) +
                               " is not fixed by the fit to 1 on any element");
  const double miss = worst_miss(space, k, degree);
  if (!(miss <= tolerance))
    throw std::runtime_error("constant_coefficients: the constants are not in the " + space.type() +
                             " space (misses 1 by " + std::to_string(miss) + ")");
  return k;
}

}  // namespace iga
