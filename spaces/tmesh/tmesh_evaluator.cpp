#include "spaces/tmesh/tmesh_space.hpp"

#include <cmath>

#include "spaces/extracted_evaluator.hpp"

namespace iga {

/// The explicit core (element_core.hpp): the tensor Bernstein basis of the cell's two section sides
/// (local index i + j (n+1); cells with the same sides share a kind), the Hermite extraction E_c,
/// and the diagonal affine map of the cell. Being tensor sections under a diagonal scaling, it also
/// gives the derivatives of order 3 and 4 the plate estimator needs.
struct TMeshSpace::Core {
  using Jet = GeometryJet;
  static constexpr bool identity = false;
  const TMeshSpace& space;
  mutable Eigen::SparseMatrix<double> e_t;  ///< E_cᵀ compressed, per core (one core per thread)

  int kind(int e) const { return space.cell_kind_[e]; }

  int tabulate(int kind, const std::vector<Point2>& points, int order, LocalTables& t) const {
    const SectionBernstein& bx = space.bernstein(space.kinds_[kind].first);
    const SectionBernstein& by = space.bernstein(space.kinds_[kind].second);
    const int m = bx.n() + 1, q = static_cast<int>(points.size()), tables = (order + 1) * (order + 2) / 2;
    const int dx[6] = {0, 1, 0, 2, 1, 0}, dy[6] = {0, 0, 1, 0, 1, 2};
    for (int d = 0; d < tables; ++d) t[d].resize(m * m, q);
    for (int k = 0; k < q; ++k) {
      const Eigen::MatrixXd X = bx.derivatives(points[k].x(), order), Y = by.derivatives(points[k].y(), order);
      for (int d = 0; d < tables; ++d)
        for (int j = 0; j < m; ++j)
          for (int i = 0; i < m; ++i) t[d](i + j * m, k) = X(dx[d], i) * Y(dy[d], j);
    }
    return order;
  }

  const std::vector<int>& active(int e) const { return space.extraction_.dofs[e]; }
  /// Built on demand: the specialisation below contracts with the dense E_c instead.
  Extraction extraction(int e) const {
    e_t = space.extraction_.matrix[e].transpose().sparseView();
    e_t.makeCompressed();
    return extraction_view(e_t);
  }

  /// x = lo + diag(h) ξ: one Jacobian, no second derivatives.
  void map(int e, const QuadratureRule& rule, const LocalTables& /*t*/, int /*order*/, std::vector<Jet>& jets) const {
    Point2 lo, hi;
    space.cell_box(e, lo, hi);
    const Point2 h = hi - lo;
    jets.resize(rule.size());
    for (int k = 0; k < rule.size(); ++k) {
      jets[k].x = lo + h.cwiseProduct(rule.points[k]);
      jets[k].jacobian = h.asDiagonal();
      jets[k].hessian_x.setZero();
      jets[k].hessian_y.setZero();
    }
  }

  /// ∇Δu_h and Δ²u_h from the Bernstein coefficients b = E_cᵀ c: the map is a diagonal scaling, so
  /// ∂x^a ∂y^b = hx^-a hy^-b ∂ξ^a ∂η^b (reference derivatives carry h^d, see SectionBernstein).
  void higher_derivatives(int e, const QuadratureRule& rule, const Eigen::VectorXd& b, unsigned higher,
                          FunctionValues& out) const {
    const TCell& cell = space.mesh().cells()[e];
    const SectionBernstein& bx = space.bernstein(side_key_x(cell));
    const SectionBernstein& by = space.bernstein(side_key_y(cell));
    const double hx = bx.h(), hy = by.h();
    const int n = bx.n(), q = rule.size();
    auto derivative = [&](const Eigen::MatrixXd& X, const Eigen::MatrixXd& Y, int ax, int ay) {
      double sum = 0.0;
      for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) sum += b(i + j * (n + 1)) * X(ax, i) * Y(ay, j);
      return sum / (std::pow(hx, ax) * std::pow(hy, ay));
    };
    if (higher & update_laplacian_gradient) out.laplacian_dx.resize(q), out.laplacian_dy.resize(q);
    if (higher & update_bilaplacian) out.bilaplacian.resize(q);
    for (int k = 0; k < q; ++k) {
      const Eigen::MatrixXd X = bx.derivatives(rule.points[k].x(), 4), Y = by.derivatives(rule.points[k].y(), 4);
      if (higher & update_laplacian_gradient) {
        out.laplacian_dx(k) = derivative(X, Y, 3, 0) + derivative(X, Y, 1, 2);
        out.laplacian_dy(k) = derivative(X, Y, 2, 1) + derivative(X, Y, 0, 3);
      }
      if (higher & update_bilaplacian)
        out.bilaplacian(k) = derivative(X, Y, 4, 0) + 2.0 * derivative(X, Y, 2, 2) + derivative(X, Y, 0, 4);
    }
  }
};

// ---------------------------------------------------------------------------------------------
// Evaluator specialisation (element_core.hpp): evaluate is the generic evaluator on the core. The
// cell map is a diagonal scaling, so the physical derivatives of u_h are its reference ones times
// powers of 1/h: evaluate_function contracts the Bernstein coefficients b = E_cᵀ c with the core's
// tables without the point-by-point push-forward, geometry is the box, and loads are E_c (φ w)
// with the dense E_c (the generic path needs E_c as a sparse view, built per call). Measured on
// tmesh-c1-plate (perf samples of one run, 164 356 DOFs): the evaluator's CPU time is 0.15 s this
// way against about 0.2 s with the generic evaluator alone (push-forward and sparse views per cell).

class TMeshSpace::TMeshEvaluator final : public Space::Evaluator {
 public:
  explicit TMeshEvaluator(const TMeshSpace& space)
      : Space::Evaluator(space), space_(space), generic_(space, Core{space, {}}) {}

  void evaluate(int element, const QuadratureRule& rule, unsigned flags, PointValues& out) override {
    generic_.evaluate(element, rule, flags, out);
  }

  /// x = lo + diag(h) ξ.
  void evaluate_geometry(int element, const QuadratureRule& rule, PointValues& out) override {
    Point2 lo, hi;
    space_.cell_box(element, lo, hi);
    const Point2 h = hi - lo;
    out.dofs = space_.extraction().dofs[element];
    out.jacobian.assign(rule.size(), Eigen::Matrix2d(h.asDiagonal()));
    out.x.resize(2, rule.size());
    for (int k = 0; k < rule.size(); ++k) out.x.col(k) = lo + h.cwiseProduct(rule.points[k]);
  }

  void integrate_values(int element, const QuadratureRule& rule, const PointValues& /*geometry*/,
                        const Eigen::VectorXd& weights, Eigen::VectorXd& local) override {
    b_.noalias() = generic_.tables(element, rule, 0)[0] * weights;
    local.noalias() = space_.extraction().matrix[element] * b_;
  }

  /// ∂x^a ∂y^b u_h(x_k) = hx^-a hy^-b Σ_l b_l ∂ξ^a ∂η^b φ_l(ξ_k).
  void evaluate_element_function(int element, const QuadratureRule& rule, const Eigen::VectorXd& local, unsigned flags,
                                 PointValues& geometry, FunctionValues& out) override {
    const LocalTables& t = generic_.tables(element, rule, basis_order(flags));
    evaluate_geometry(element, rule, geometry);
    const Eigen::Vector2d h = geometry.jacobian[0].diagonal();
    c_.resize(geometry.num_functions());
    for (int a = 0; a < c_.size(); ++a) c_(a) = local(a);
    b_.noalias() = space_.extraction().matrix[element].transpose() * c_;
    auto derivative = [&](int table, double scale, Eigen::VectorXd& v) {
      v.noalias() = scale * (t[table].transpose() * b_);
    };
    if (flags & update_values) derivative(0, 1.0, out.value);
    if (flags & update_gradients) {
      derivative(1, 1.0 / h.x(), out.dx);
      derivative(2, 1.0 / h.y(), out.dy);
    }
    if (flags & update_hessians) {
      derivative(3, 1.0 / (h.x() * h.x()), out.dxx);
      derivative(4, 1.0 / (h.x() * h.y()), out.dxy);
      derivative(5, 1.0 / (h.y() * h.y()), out.dyy);
    }
    const unsigned higher = flags & (update_laplacian_gradient | update_bilaplacian);
    if (higher) Core{space_, {}}.higher_derivatives(element, rule, b_, higher, out);
  }

 private:
  const TMeshSpace& space_;
  ExtractedEvaluator<Core> generic_;
  Eigen::VectorXd c_, b_;
};

std::unique_ptr<Space::Evaluator> TMeshSpace::make_evaluator() const { return std::make_unique<TMeshEvaluator>(*this); }

std::unique_ptr<Space::Evaluator> TMeshSpace::make_generic_evaluator() const {
  return std::make_unique<ExtractedEvaluator<Core>>(*this, Core{*this, {}});
}

}  // namespace iga
