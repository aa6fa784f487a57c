#include "assembly/shell_integrators.hpp"

#include <Eigen/Core>

namespace iga {

double ShellMaterial::membrane_stiffness() const {
  return youngs_modulus * thickness / (1.0 - poisson_ratio * poisson_ratio);
}

double ShellMaterial::bending_stiffness() const {
  return youngs_modulus * thickness * thickness * thickness / (12.0 * (1.0 - poisson_ratio * poisson_ratio));
}

Eigen::Matrix3d membrane_strain(const PointValues& v, int i, int c, int k) {
  const Eigen::Vector3d n = v.normal3.col(k);
  const Eigen::Vector3d g = v.gradient(i, k);               // ∇_Γ N_i (tangential)
  const Eigen::Vector3d p = Eigen::Vector3d::Unit(c) - n(c) * n;  // P e_c
  const Eigen::Matrix3d pg = p * g.transpose();              // P G for G = e_c ⊗ ∇_Γ N_i
  return 0.5 * (pg + pg.transpose());
}

Eigen::Matrix3d bending_strain(const PointValues& v, int i, int c, int k) {
  return v.normal3(c, k) * v.hessian(i, k);
}

namespace {

/// The six independent entries of a symmetric strain (xx, yy, zz, xy, xz, yz) with the factors of
/// the Frobenius product (off-diagonal entries twice), and its trace: seven squares in all.
constexpr int kEntries = 6;
constexpr int kRows[kEntries] = {0, 1, 2, 0, 0, 1}, kCols[kEntries] = {0, 1, 2, 1, 2, 2};
constexpr double kFrobenius[kEntries] = {1, 1, 1, 2, 2, 2};

class ShellIntegrator final : public Integrator {
 public:
  ShellIntegrator(ShellEnergy part, const ShellMaterial& m)
      : Integrator(part == ShellEnergy::membrane ? m.membrane_stiffness() : m.bending_stiffness()),
        part_(part),
        nu_(m.poisson_ratio) {}
  unsigned flags() const override {
    return update_gradients | update_surface_curvature | (part_ == ShellEnergy::bending ? update_hessians : 0u);
  }
  std::string name() const override {
    return part_ == ShellEnergy::membrane ? "shell membrane" : "shell bending";
  }

 protected:
  void unit_matrix(const ElementValues& ev, Eigen::MatrixXd& local) const override {
    const PointValues& v = ev.values();
    const int n = ev.num_functions(), q = ev.num_points();
    // Operands: the strain entries of each function N_i e_c (rows c·n + i) at every point.
    thread_local Eigen::MatrixXd entries[kEntries], trace;
    for (auto& m : entries) m.resize(3 * n, q);
    trace.resize(3 * n, q);
    for (int k = 0; k < q; ++k)
      for (int c = 0; c < 3; ++c)
        for (int i = 0; i < n; ++i) {
          const Eigen::Matrix3d s = part_ == ShellEnergy::membrane ? membrane_strain(v, i, c, k) : bending_strain(v, i, c, k);
          for (int t = 0; t < kEntries; ++t) entries[t](c * n + i, k) = s(kRows[t], kCols[t]);
          trace(c * n + i, k) = s.trace();
        }
    const Eigen::VectorXd& w = ev.jxw();
    local.setZero(3 * n, 3 * n);
    for (int t = 0; t < kEntries; ++t)
      local.noalias() += ((1.0 - nu_) * kFrobenius[t]) * (entries[t] * w.asDiagonal() * entries[t].transpose());
    if (nu_ != 0.0) local.noalias() += nu_ * (trace * w.asDiagonal() * trace.transpose());
  }
  void unit_matrix(const ElementValues& ev, MatrixXld& local) const override {
    Eigen::MatrixXd d;
    unit_matrix(ev, d);
    local = d.cast<long double>();
  }
  void unit_matrix(const ElementValues& ev, DoubleDoubleMatrix& local) const override {
    Eigen::MatrixXd d;
    unit_matrix(ev, d);
    local = DoubleDoubleMatrix::from_long_double(MatrixXld(d.cast<long double>()));
  }

 private:
  ShellEnergy part_;
  double nu_;
};

}  // namespace

std::shared_ptr<const Integrator> shell_integrator(ShellEnergy part, const ShellMaterial& material) {
  return std::make_shared<const ShellIntegrator>(part, material);
}

}  // namespace iga
