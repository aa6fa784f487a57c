#include "solver/constant_kernel.hpp"

#include "assembly/constant_coefficients.hpp"
#include "assembly/surface_load.hpp"

namespace iga {

const Eigen::VectorXd& ConstantKernel::constant(const Space& space) {
  if (k_.size() != space.dimension()) k_ = constant_coefficients(space);
  return k_;
}

void ConstantKernel::make_load_orthogonal(Eigen::VectorXd& b, const Space& space, int quadrature_degree,
                                          const WorkShare& share) {
  const Eigen::VectorXd& k = constant(space);
  mass_of_one_ = surface_load(
      space, [](const Eigen::Vector3d&, const Eigen::Vector3d&, double) { return 1.0; }, quadrature_degree,
      share.elements);
  area_ = share.sum(mass_of_one_.dot(k));  // Σ_i k_i ∫ N_i = ∫ 1
  b -= (share.sum(b.dot(k)) / area_) * mass_of_one_;
}

Constraints ConstantKernel::pinned(const Space& space) {
  const Eigen::VectorXd& k = constant(space);
  int pin = 0;
  k.cwiseAbs().maxCoeff(&pin);
  Constraints c;
  c.values = Eigen::VectorXd::Zero(space.dimension());
  c.constrained = {pin};
  for (int i = 0; i < space.dimension(); ++i)
    if (i != pin) c.free.push_back(i);
  return c;
}

void ConstantKernel::finish(Eigen::VectorXd& coefficients, const Space& space,
                            const std::optional<SymbolicFunction>& exact, const WorkShare& share) {
  const Eigen::VectorXd& k = constant(space);
  double mean = share.sum(mass_of_one_.dot(coefficients)) / area_;
  if (exact) {
    // The mean of u_h − u, both by the error norms' rule: on a curved surface the load's rule
    // integrates √det G less accurately (a difference of 1e-7 relative on the coarse 4-split cube),
    // and that would show as a constant error. ∫v = Σ_i k_i ∫v N_i.
    const int degree = space.error_quadrature_degree();
    const SymbolicFunction u = *exact;
    const Eigen::VectorXd one_moments = surface_load(
        space, [](const Eigen::Vector3d&, const Eigen::Vector3d&, double) { return 1.0; }, degree, share.elements);
    const Eigen::VectorXd u_moments = surface_load(
        space, [u](const Eigen::Vector3d& x, const Eigen::Vector3d&, double) { return u.at(x); }, degree,
        share.elements);
    mean = (share.sum(one_moments.dot(coefficients)) - share.sum(u_moments.dot(k))) / share.sum(one_moments.dot(k));
  }
  coefficients -= mean * k;
}

}  // namespace iga
