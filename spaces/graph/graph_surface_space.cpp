#include "spaces/graph/graph_surface_space.hpp"

#include <array>
#include <stdexcept>

#include "geometry/surface_jet.hpp"
#include "spaces/surface_values.hpp"

namespace iga {

namespace {

/// The per-thread evaluator: the planar one, then the lift.
class GraphEvaluator final : public Space::Evaluator {
 public:
  explicit GraphEvaluator(const GraphSurfaceSpace& space)
      : Space::Evaluator(space), space_(space), planar_(space.planar().make_evaluator()) {}

  void evaluate(int element, const QuadratureRule& rule, unsigned flags, PointValues& out) override {
    const bool second = flags & (update_hessians | update_surface_curvature);
    unsigned planar_flags = flags & (update_values | update_gradients | update_hessians);
    if (flags & update_hessians) planar_flags |= update_gradients;  // the Christoffel term
    planar_->evaluate(element, rule, planar_flags, p_);
    lift(flags, second, out);
    out.dofs = p_.dofs;
    if (flags & update_values) out.value = p_.value;
    if (flags & (update_gradients | update_hessians)) complete_surface_gradients(jets_, p_.dx, p_.dy, out);
    if (flags & update_hessians) complete_surface_hessians(jets_, p_.dx, p_.dy, {p_.dxx, p_.dxy, p_.dyy}, out);
  }

  void evaluate_element_function(int element, const QuadratureRule& rule, const Eigen::VectorXd& local, unsigned flags,
                                 PointValues& geometry, FunctionValues& out) override {
    if (flags & (update_laplacian_gradient | update_bilaplacian))
      throw std::logic_error("evaluate_function: a graph surface provides derivatives up to order 2 only");
    const bool second = flags & (update_hessians | update_surface_curvature);
    unsigned planar_flags = update_values | (flags & (update_gradients | update_hessians));
    if (flags & update_hessians) planar_flags |= update_gradients;
    planar_->evaluate_element_function(element, rule, local, planar_flags, p_, f_);
    lift(flags, second, geometry);
    geometry.dofs = p_.dofs;
    out.value = f_.value;
    if (flags & (update_gradients | update_hessians)) {
      // One function: its planar derivatives as 1 × q rows through the same completion.
      dx_ = f_.dx.transpose();
      dy_ = f_.dy.transpose();
      complete_surface_gradients(jets_, dx_, dy_, one_);
      out.dx = one_.dx.row(0).transpose();
      out.dy = one_.dy.row(0).transpose();
      out.dz = one_.dz.row(0).transpose();
    }
    if (flags & update_hessians) {
      dxx_ = f_.dxx.transpose();
      dxy_ = f_.dxy.transpose();
      dyy_ = f_.dyy.transpose();
      complete_surface_hessians(jets_, dx_, dy_, {dxx_, dxy_, dyy_}, one_);
      out.dxx = one_.dxx.row(0).transpose();
      out.dxy = one_.dxy.row(0).transpose();
      out.dyy = one_.dyy.row(0).transpose();
      out.dxz = one_.dxz.row(0).transpose();
      out.dyz = one_.dyz.row(0).transpose();
      out.dzz = one_.dzz.row(0).transpose();
    }
  }

  void evaluate_geometry(int element, const QuadratureRule& rule, PointValues& out) override {
    planar_->evaluate_geometry(element, rule, p_);
    lift(0u, false, out);
    out.dofs = p_.dofs;
  }

  /// The planar space's transposed evaluation, on the planar geometry of the last evaluate_geometry.
  void integrate_values(int element, const QuadratureRule& rule, const PointValues& /*geometry*/,
                        const Eigen::VectorXd& weights, Eigen::VectorXd& local) override {
    planar_->integrate_values(element, rule, p_, weights, local);
  }

 private:
  /// The lift's jets at the planar points of p_, and the geometry members of `out`: x3, x (planar),
  /// jacobian3 = J_X J_planar, jacobian (planar), with `flags` normal3 and mean_curvature.
  void lift(unsigned flags, bool second, PointValues& out) {
    const int q = static_cast<int>(p_.x.cols());
    space_.height_jets(p_.x, g_);
    jets_.resize(q);
    for (int k = 0; k < q; ++k) {
      const Eigen::Vector3d x(p_.x(0, k), p_.x(1, k), g_(0, k));
      Eigen::Matrix<double, 3, 2> J;
      J << 1, 0, 0, 1, g_(1, k), g_(2, k);
      const std::array<Eigen::Vector3d, 3> xab{Eigen::Vector3d(0, 0, g_(3, k)), Eigen::Vector3d(0, 0, g_(4, k)),
                                               Eigen::Vector3d(0, 0, g_(5, k))};
      fill_surface_jet(jets_[k], x, J, second ? &xab : nullptr);
    }
    take_surface_geometry(jets_, flags, out);
    for (int k = 0; k < q; ++k) out.jacobian3[k] = jets_[k].jacobian * p_.jacobian[k];
    out.jacobian = p_.jacobian;
  }

  const GraphSurfaceSpace& space_;
  std::unique_ptr<Space::Evaluator> planar_;
  PointValues p_, one_;
  FunctionValues f_;
  Eigen::MatrixXd g_, dx_, dy_, dxx_, dxy_, dyy_;
  std::vector<SurfaceJet> jets_;
};

}  // namespace

GraphSurfaceSpace::GraphSurfaceSpace(SpacePtr planar, const SymbolicFunction& height, const std::string& height_text)
    : planar_(std::move(planar)),
      height_({height, height.diff_x(), height.diff_y(), height.diff_x().diff_x(), height.diff_x().diff_y(),
               height.diff_y().diff_y()}) {
  if (planar_->ambient_dimension() != 2) throw std::logic_error("GraphSurfaceSpace: the base space is not planar");
  SpaceFacts f = planar_->facts();
  f.parameters.emplace_back("surface", "z = " + height_text);
  f.ambient_dimension = 3;
  f.affine_elements = false;       // the lift is not affine: assembly rules of degree 2p + 3
  f.higher_derivatives = false;    // third derivatives of the lift are not carried
  // h stays the planar element diameter: the lift is bi-Lipschitz, so rates in it are the rates.
  set_facts(std::move(f));
}

Eigen::Vector3d GraphSurfaceSpace::lift(const Point2& p) const {
  Eigen::MatrixXd g;
  height_jets(p, g);
  return {p.x(), p.y(), g(0, 0)};
}

Eigen::Matrix<double, 3, 2> GraphSurfaceSpace::lift_jacobian(const Point2& p) const {
  Eigen::MatrixXd g;
  height_jets(p, g);
  Eigen::Matrix<double, 3, 2> J;
  J << 1, 0, 0, 1, g(1, 0), g(2, 0);
  return J;
}

std::unique_ptr<Space::Evaluator> GraphSurfaceSpace::make_evaluator() const {
  return std::make_unique<GraphEvaluator>(*this);
}

}  // namespace iga
