#include "spaces/tmesh/tmesh_space.hpp"

#include <algorithm>
#include <cmath>

#include "spaces/push_forward.hpp"

namespace iga {

// ---------------------------------------------------------------------------------------------
// Evaluator: Bernstein tables per (rule, cell size), then per cell only E_c times the tensor table.

class TMeshSpace::TMeshEvaluator final : public Space::Evaluator {
 public:
  explicit TMeshEvaluator(const TMeshSpace& space) : space_(space) {}
  void evaluate(int element, const QuadratureRule& rule, unsigned flags, PointValues& out) override;
  /// Adds ∇Δu_h and Δ²u_h: the cell map is a diagonal scaling, so ∂x^a ∂y^b = hx^-a hy^-b ∂ξ^a ∂η^b
  /// of the Bernstein coefficients E_cᵀ c.
  void evaluate_function(int element, const QuadratureRule& rule, const Eigen::VectorXd& coefficients, unsigned flags,
                         PointValues& geometry, FunctionValues& out) override;
  /// Points and the (diagonal) Jacobian only: no function values.
  void evaluate_geometry(int element, const QuadratureRule& rule, PointValues& out) override;
  /// Σ_q w_q N_a(x_q) = E_c b with b_ij = Σ_q w_q B_i(ξ_q) B_j(η_q): the tensor Bernstein sums
  /// first, then one small matrix-vector product (no table of every active function).
  void integrate_values(int element, const QuadratureRule& rule, const PointValues& geometry,
                        const Eigen::VectorXd& weights, Eigen::VectorXd& local) override;

 private:
  /// dofs, x and the Jacobian of `element` at the points of `rule`.
  void fill_geometry(int element, const QuadratureRule& rule, PointValues& out) const;

  /// Reference derivatives (orders 0..2) of the Bernstein basis along x and y: (n+1) x q each.
  struct Tables {
    std::vector<Point2> points;
    Eigen::MatrixXd bx[3], by[3];
  };
  const Tables& tables(const QuadratureRule& rule, const TCell& cell);

  const TMeshSpace& space_;
  std::map<std::tuple<const QuadratureRule*, int, int, std::int64_t, std::int64_t>, Tables> cache_;
  Eigen::MatrixXd local_[6];
  Eigen::VectorXd sums_, c_, b_;
  Eigen::MatrixXd by_[3];
  ReferenceDerivatives ref_;
  std::vector<GeometryJet> jets_;
};

namespace {

/// The evaluator's loops over the n+1 Bernstein functions of a direction, with n+1 as a template
/// parameter for the usual sizes (fixed-size Eigen blocks unroll and vectorize; the tables have
/// q columns) and Eigen::Dynamic for the others.
template <class F>
void with_size(int m, F&& f) {
  switch (m) {
    case 3: f(std::integral_constant<int, 3>{}); break;
    case 4: f(std::integral_constant<int, 4>{}); break;
    case 5: f(std::integral_constant<int, 5>{}); break;
    case 6: f(std::integral_constant<int, 6>{}); break;
    default: f(std::integral_constant<int, Eigen::Dynamic>{}); break;
  }
}

template <int M>
using Rows = Eigen::Matrix<double, M, Eigen::Dynamic>;

/// by = B Y with B the m x m array of b (column-major), Y m x q.
template <int M>
void times_table(const Eigen::VectorXd& b, const Eigen::MatrixXd& Y, Eigen::MatrixXd& by) {
  const Eigen::Index m = Y.rows(), q = Y.cols();
  const Eigen::Map<const Eigen::Matrix<double, M, M>> B(b.data(), m, m);
  by.resize(m, q);
  Eigen::Map<Rows<M>>(by.data(), m, q).noalias() = B.lazyProduct(Eigen::Map<const Rows<M>>(Y.data(), m, q));
}

/// v(k) = scale Σ_i X(i, k) Y(i, k).
template <int M>
void column_dots(const Eigen::MatrixXd& X, const Eigen::MatrixXd& Y, double scale, Eigen::VectorXd& v) {
  const Eigen::Index m = X.rows(), q = X.cols();
  const Eigen::Map<const Rows<M>> XM(X.data(), m, q), YM(Y.data(), m, q);
  v.noalias() = XM.cwiseProduct(YM).colwise().sum().transpose() * scale;
}

/// sums(i + j m) = Σ_k w_k X(i, k) Y(j, k).
template <int M>
void weighted_tensor_sums(const Eigen::MatrixXd& X, const Eigen::MatrixXd& Y, const Eigen::VectorXd& w, Eigen::VectorXd& sums) {
  const Eigen::Index m = X.rows(), q = X.cols();
  sums.setZero(m * m);
  Eigen::Map<Eigen::Matrix<double, M, M>> S(sums.data(), m, m);
  const Eigen::Map<const Rows<M>> XM(X.data(), m, q), YM(Y.data(), m, q);
  for (Eigen::Index k = 0; k < q; ++k) S.noalias() += (w(k) * XM.col(k)) * YM.col(k).transpose();
}

}  // namespace

const TMeshSpace::TMeshEvaluator::Tables& TMeshSpace::TMeshEvaluator::tables(const QuadratureRule& rule,
                                                                           const TCell& cell) {
  const std::int64_t lx = cell.x1 - cell.x0, ly = cell.y1 - cell.y0;
  const auto key = std::make_tuple(&rule, cell.section_s, cell.section_t, lx, ly);
  auto it = cache_.find(key);
  if (it != cache_.end() && it->second.points == rule.points) return it->second;
  if (it == cache_.end() && cache_.size() >= 256) cache_.clear();
  Tables& t = cache_[key];
  t.points = rule.points;
  const SectionBernstein& bx = space_.bernstein(TMeshSpace::side_x(cell));
  const SectionBernstein& by = space_.bernstein(TMeshSpace::side_y(cell));
  const int n = bx.n(), q = rule.size();
  for (int d = 0; d < 3; ++d) {
    t.bx[d].resize(n + 1, q);
    t.by[d].resize(n + 1, q);
  }
  for (int k = 0; k < q; ++k) {
    const Eigen::MatrixXd dx = bx.derivatives(rule.points[k].x(), 2), dy = by.derivatives(rule.points[k].y(), 2);
    for (int d = 0; d < 3; ++d) {
      t.bx[d].col(k) = dx.row(d).transpose();
      t.by[d].col(k) = dy.row(d).transpose();
    }
  }
  return t;
}

void TMeshSpace::TMeshEvaluator::evaluate(int element, const QuadratureRule& rule, unsigned flags, PointValues& out) {
  Point2 lo, hi;
  space_.cell_box(element, lo, hi);
  const Point2 h = hi - lo;
  const TCell& cell = space_.mesh().cells()[element];
  const Tables& t = tables(rule, cell);
  const int n = space_.section().n, q = rule.size(), nl = (n + 1) * (n + 1);
  const bool values = (flags & update_values) != 0;
  const bool grads = (flags & (update_gradients | update_hessians)) != 0;
  const bool hess = (flags & update_hessians) != 0;
  // Tensor Bernstein data: 0 value, 1 d/dxi, 2 d/deta, 3 d2/dxi2, 4 d2/dxideta, 5 d2/deta2.
  const int orders[6][2] = {{0, 0}, {1, 0}, {0, 1}, {2, 0}, {1, 1}, {0, 2}};
  const bool want[6] = {values, grads, grads, hess, hess, hess};
  for (int a = 0; a < 6; ++a) {
    if (!want[a]) continue;
    local_[a].resize(nl, q);
    const Eigen::MatrixXd &X = t.bx[orders[a][0]], &Y = t.by[orders[a][1]];
    for (int k = 0; k < q; ++k)
      for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) local_[a](i + j * (n + 1), k) = X(i, k) * Y(j, k);
  }
  const Eigen::MatrixXd& E = space_.extraction().matrix[element];
  Eigen::MatrixXd* dst[6] = {&ref_.value, &ref_.dxi, &ref_.deta, &ref_.dxixi, &ref_.dxieta, &ref_.detaeta};
  for (int a = 0; a < 6; ++a)
    if (want[a]) dst[a]->noalias() = E * local_[a];
  out.dofs = space_.extraction().dofs[element];
  jets_.resize(q);
  Eigen::Matrix2d J = Eigen::Matrix2d::Zero();
  J(0, 0) = h.x();
  J(1, 1) = h.y();
  for (int k = 0; k < q; ++k) {
    jets_[k].jacobian = J;
    jets_[k].x = lo + h.cwiseProduct(rule.points[k]);
    jets_[k].hessian_x.setZero();
    jets_[k].hessian_y.setZero();
  }
  push_forward(jets_, ref_, flags, out);
}

void TMeshSpace::TMeshEvaluator::fill_geometry(int element, const QuadratureRule& rule, PointValues& out) const {
  Point2 lo, hi;
  space_.cell_box(element, lo, hi);
  const Point2 h = hi - lo;
  const int q = rule.size();
  out.dofs = space_.extraction().dofs[element];
  Eigen::Matrix2d J = Eigen::Matrix2d::Zero();
  J(0, 0) = h.x();
  J(1, 1) = h.y();
  out.jacobian.assign(q, J);
  out.x.resize(2, q);
  for (int k = 0; k < q; ++k) out.x.col(k) = lo + h.cwiseProduct(rule.points[k]);
}

void TMeshSpace::TMeshEvaluator::evaluate_geometry(int element, const QuadratureRule& rule, PointValues& out) {
  fill_geometry(element, rule, out);
}

void TMeshSpace::TMeshEvaluator::integrate_values(int element, const QuadratureRule& rule, const PointValues&,
                                                  const Eigen::VectorXd& weights, Eigen::VectorXd& local) {
  const Tables& t = tables(rule, space_.mesh().cells()[element]);
  const Eigen::MatrixXd& X = t.bx[0];
  const Eigen::MatrixXd& Y = t.by[0];
  const int m = static_cast<int>(X.rows());
  with_size(m, [&](auto size) { weighted_tensor_sums<decltype(size)::value>(X, Y, weights, sums_); });
  local.noalias() = space_.extraction().matrix[element].lazyProduct(sums_);
}

void TMeshSpace::TMeshEvaluator::evaluate_function(int element, const QuadratureRule& rule,
                                                   const Eigen::VectorXd& coefficients, unsigned flags,
                                                   PointValues& geometry, FunctionValues& out) {
  const unsigned higher = flags & (update_laplacian_gradient | update_bilaplacian);
  // u_h on the cell in its tensor Bernstein basis first: b = E_cᵀ c (index i + j (n+1)), then
  // ∂ξ^a ∂η^b u_h(x_k) = X_a(:, k)ᵀ B Y_b(:, k) with B = b as an (n+1) x (n+1) array, from the
  // cached 1D tables: no table of every active function (what the error norms would otherwise pay).
  const TCell& cell = space_.mesh().cells()[element];
  const Tables& t = tables(rule, cell);
  const int q = rule.size();
  fill_geometry(element, rule, geometry);
  Point2 lo, hi;
  space_.cell_box(element, lo, hi);
  const Point2 h = hi - lo;
  const Eigen::MatrixXd& E = space_.extraction().matrix[element];
  c_.resize(geometry.num_functions());
  for (int a = 0; a < c_.size(); ++a) c_(a) = coefficients(geometry.dofs[a]);
  b_.noalias() = E.transpose().lazyProduct(c_);
  const Eigen::VectorXd& b = b_;
  {
    const int m = space_.section().n + 1;
    const bool grads = (flags & (update_gradients | update_hessians)) != 0, hess = (flags & update_hessians) != 0;
    // B Y_d: (n+1) x (n+1) times (n+1) x q, coefficient-based (GEMM packing costs more at this size).
    with_size(m, [&](auto size) {
      for (int d = 0; d <= (hess ? 2 : grads ? 1 : 0); ++d) times_table<decltype(size)::value>(b, t.by[d], by_[d]);
    });
    auto derivative = [&](int ax, int ay, double scale, Eigen::VectorXd& v) {
      with_size(m, [&](auto size) { column_dots<decltype(size)::value>(t.bx[ax], by_[ay], scale, v); });
    };
    if ((flags & update_values) || higher) derivative(0, 0, 1.0, out.value);
    if (flags & update_gradients) {
      derivative(1, 0, 1.0 / h.x(), out.dx);
      derivative(0, 1, 1.0 / h.y(), out.dy);
    }
    if (flags & update_hessians) {
      derivative(2, 0, 1.0 / (h.x() * h.x()), out.dxx);
      derivative(1, 1, 1.0 / (h.x() * h.y()), out.dxy);
      derivative(0, 2, 1.0 / (h.y() * h.y()), out.dyy);
    }
  }
  if (!higher) return;
  const SectionBernstein& bx = space_.bernstein(TMeshSpace::side_x(cell));
  const SectionBernstein& by = space_.bernstein(TMeshSpace::side_y(cell));
  const double hx = bx.h(), hy = by.h();
  const int n = bx.n();
  // D(a, b) = ∂x^a ∂y^b u_h at point k (reference derivatives carry h^d, see SectionBernstein).
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

std::unique_ptr<Space::Evaluator> TMeshSpace::make_evaluator() const { return std::make_unique<TMeshEvaluator>(*this); }

}  // namespace iga
