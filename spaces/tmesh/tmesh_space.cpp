#include "spaces/tmesh/tmesh_space.hpp"
#include "config/worth_threads.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <numbers>
#include <span>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <tuple>
#include <type_traits>

#include "config/errors.hpp"
#include "spaces/push_forward.hpp"
#include "spaces/tmesh/tmesh_refinement.hpp"

namespace iga {

namespace {
/// Extra degree of the rules of trigonometric and hyperbolic sections on coarse cells.
constexpr int kFullExtraDegree = 16;
}  // namespace

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
  const SectionBernstein& bx = space_.bernstein(cell.section_s, lx);
  const SectionBernstein& by = space_.bernstein(cell.section_t, ly);
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
  const SectionBernstein& bx = space_.bernstein(cell.section_s, cell.x1 - cell.x0);
  const SectionBernstein& by = space_.bernstein(cell.section_t, cell.y1 - cell.y0);
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

// ---------------------------------------------------------------------------------------------

TMeshSpace::TMeshSpace(TMesh mesh, int regularity, bool rectangular, std::string domain_description)
    : mesh_(std::move(mesh)), r_(regularity), rectangular_(rectangular), domain_(std::move(domain_description)) {
  // Space::boundary_edges can only name whole element edges.
  if (mesh_.has_partial_boundary_sides())
    throw std::invalid_argument(
        "a cell side lies partly on the boundary (a re-entrant corner inside a cell side); boundary edges "
        "of the Space interface are whole element edges, so refine that cell first");
  extraction_ = hermite_extraction(mesh_, r_);
  normalize_basis();
  // Exact lattice lengths as keys: dyadic meshes have a handful of distinct cell sizes.
  for (int c = 0; c < mesh_.num_cells(); ++c) {
    const TCell& cell = mesh_.cells()[c];
    const std::pair<int, std::int64_t> kx{cell.section_s, cell.x1 - cell.x0}, ky{cell.section_t, cell.y1 - cell.y0};
    if (!bernstein_.count(kx)) bernstein_.emplace(kx, SectionBernstein(mesh_.sections()[kx.first], mesh_.width(c)));
    if (!bernstein_.count(ky)) bernstein_.emplace(ky, SectionBernstein(mesh_.sections()[ky.first], mesh_.height(c)));
  }
  for (int c = 0; c < mesh_.num_cells(); ++c) mesh_size_ = std::max(mesh_size_, std::hypot(mesh_.width(c), mesh_.height(c)));
  // Extra degree of every rule for the largest w h of a non-polynomial section.
  double wh = 0.0;
  for (int c = 0; c < mesh_.num_cells(); ++c) {
    const SectionSpec &sx = mesh_.sections()[mesh_.cells()[c].section_s], &sy = mesh_.sections()[mesh_.cells()[c].section_t];
    if (sx.family != SectionFamily::polynomial) wh = std::max(wh, sx.w * mesh_.width(c));
    if (sy.family != SectionFamily::polynomial) wh = std::max(wh, sy.w * mesh_.height(c));
  }
  extra_degree_ = non_polynomial_extra_degree(wh);
  // Side integrals with the 1D Gauss rule of the assembly's tensor rule on coarse cells, and with
  // that rule's 8 extra points on fine ones too: the closed-form matrices go to the double-double
  // solve, where a quadrature error of 1e-17 is not round-off (the plate's L2 error moved by
  // 2e-4 relative with 4 extra points at w h = pi/128). They are computed once per side length.
  const int n = section().n;
  const QuadratureRule gauss = gauss_legendre_for_degree(2 * n + 1 + (extra_degree_ > 0 ? kFullExtraDegree : 0));
  for (const auto& [key, b] : bernstein_) {
    SideIntegrals& s = side_integrals_[key];
    for (auto& m : s.m) m.setZero(b.n() + 1, b.n() + 1);
    for (int k = 0; k < gauss.size(); ++k) {
      const Eigen::MatrixXd d = b.derivatives(gauss.points[k].x(), 2);
      const long double w = gauss.weights[k];
      for (int a = 0; a < 3; ++a)
        for (int c = 0; c < 3; ++c)
          for (int j = 0; j <= b.n(); ++j)
            for (int i = 0; i <= b.n(); ++i)
              s.m[3 * a + c](i, j) += w * static_cast<long double>(d(a, i)) * static_cast<long double>(d(c, j));
    }
    // Double-double: w d_i exact (two-product), then times d_j, summed with compensated additions.
    SideIntegralsDD& sd = side_integrals_dd_[key];
    sd.size = b.n() + 1;
    for (auto& m : sd.m) m.assign(sd.size * sd.size, DoubleDouble(0.0));
    for (int k = 0; k < gauss.size(); ++k) {
      const Eigen::MatrixXd d = b.derivatives(gauss.points[k].x(), 2);
      const double w = gauss.weights[k];
      for (int a = 0; a < 3; ++a)
        for (int c = 0; c < 3; ++c)
          for (int j = 0; j < sd.size; ++j)
            for (int i = 0; i < sd.size; ++i)
              sd.m[3 * a + c][i + sd.size * j] += dd_detail::two_prod(w, d(a, i)) * d(c, j);
    }
  }
  static std::atomic<std::uint64_t> next_instance{1};
  instance_id_ = next_instance++;
}

namespace {

/// Terms c ∫ ∂x^a ∂y^b u ∂x^a' ∂y^b' v of each form = c hx hy hx^-(a+a') hy^-(b+b') X(a, a') ⊗ Y(b, b').
struct FormTerm {
  int a, b, a2, b2, c;
};
std::span<const FormTerm> form_terms(BilinearForm form) {
  static constexpr FormTerm mass[] = {{0, 0, 0, 0, 1}}, laplace[] = {{1, 0, 1, 0, 1}, {0, 1, 0, 1, 1}},
                            bilaplace[] = {{2, 0, 2, 0, 1}, {2, 0, 0, 2, 1}, {0, 2, 2, 0, 1}, {0, 2, 0, 2, 1}},
                            hessian[] = {{2, 0, 2, 0, 1}, {1, 1, 1, 1, 2}, {0, 2, 0, 2, 1}};
  switch (form) {
    case BilinearForm::mass: return mass;
    case BilinearForm::laplace: return laplace;
    case BilinearForm::bilaplace: return bilaplace;
    case BilinearForm::hessian: return hessian;
  }
  return {};
}

/// x^p in double-double (p small).
DoubleDouble power(double x, int p) {
  DoubleDouble r(1.0);
  for (int k = 0; k < p; ++k) r = r * x;
  return r;
}

}  // namespace

bool TMeshSpace::closed_form_element_matrix_double_double(int element, BilinearForm form,
                                                          DoubleDoubleMatrix& local) const {
  const TCell& cell = mesh_.cells()[element];
  // K_c depends on the form, the sections and the side lengths only: a dyadic mesh has a handful,
  // so each thread keeps them (keyed by this space, whose id no later space reuses).
  using Key = std::tuple<int, int, std::int64_t, int, std::int64_t>;
  struct CellMatrix {
    int size = 0;
    std::vector<double> hi, lo;  // column-major, size x size
  };
  struct Cache {
    std::uint64_t owner = 0;
    std::map<Key, CellMatrix> matrices;
  };
  thread_local Cache cache;
  if (cache.owner != instance_id_) {
    cache.owner = instance_id_;
    cache.matrices.clear();
  }
  const Key key{static_cast<int>(form), cell.section_s, cell.x1 - cell.x0, cell.section_t, cell.y1 - cell.y0};
  auto it = cache.matrices.find(key);
  if (it == cache.matrices.end()) {
    const SideIntegralsDD& sx = side_integrals_dd_.at({cell.section_s, cell.x1 - cell.x0});
    const SideIntegralsDD& sy = side_integrals_dd_.at({cell.section_t, cell.y1 - cell.y0});
    const double hx = mesh_.width(element), hy = mesh_.height(element);
    const int nx = sx.size, ny = sy.size, nl = nx * ny;
    std::vector<DoubleDouble> k(static_cast<std::size_t>(nl) * nl, DoubleDouble(0.0));
    for (const FormTerm& t : form_terms(form)) {
      const DoubleDouble scale =
          dd_detail::two_prod(hx, hy) * static_cast<double>(t.c) / (power(hx, t.a + t.a2) * power(hy, t.b + t.b2));
      const std::vector<DoubleDouble>& X = sx.m[3 * t.a + t.a2];
      const std::vector<DoubleDouble>& Y = sy.m[3 * t.b + t.b2];
      for (int j2 = 0; j2 < ny; ++j2)
        for (int i2 = 0; i2 < nx; ++i2)
          for (int j = 0; j < ny; ++j) {
            const DoubleDouble yv = scale * Y[j + ny * j2];
            for (int i = 0; i < nx; ++i) k[(i + nx * j) + nl * (i2 + nx * j2)] += X[i + nx * i2] * yv;
          }
    }
    CellMatrix m;
    m.size = nl;
    m.hi.resize(k.size());
    m.lo.resize(k.size());
    for (std::size_t q = 0; q < k.size(); ++q) m.hi[q] = k[q].hi, m.lo[q] = k[q].lo;
    it = cache.matrices.emplace(key, std::move(m)).first;
  }
  const CellMatrix& k = it->second;
  const Eigen::MatrixXd& e = extraction_.matrix[element];
  // Cells of one size away from T-junctions and the boundary share E_c as well (the same Hermite
  // functions, the same scaling): their matrices are computed once, looked up by the bytes of E_c.
  struct Known {
    Eigen::MatrixXd e;
    DoubleDoubleMatrix local;
  };
  thread_local std::map<std::pair<const CellMatrix*, std::size_t>, std::vector<Known>> known;
  thread_local std::uint64_t known_owner = 0;
  thread_local std::size_t known_count = 0;
  if (known_owner != instance_id_ || known_count > 1024) {  // bounded (a few MB): graded meshes have many
    known_owner = instance_id_;
    known.clear();
    known_count = 0;
  }
  const std::size_t hash = std::hash<std::string_view>{}(
      std::string_view(reinterpret_cast<const char*>(e.data()), static_cast<std::size_t>(e.size()) * sizeof(double)));
  std::vector<Known>& same_hash = known[{&k, hash}];
  for (const Known& c : same_hash)
    if (c.e.rows() == e.rows() && c.e.cols() == e.cols() && c.e == e) {
      local = c.local;
      return true;
    }
  const int na = static_cast<int>(e.rows()), nl = k.size;
  // The nonzeros of each row of E_c (a vertex or edge function touches a corner or side block of
  // the cell's Bernstein coefficients only).
  thread_local std::vector<int> start, column;
  thread_local std::vector<double> value;
  start.assign(1, 0);
  column.clear();
  value.clear();
  for (int a = 0; a < na; ++a) {
    for (int p = 0; p < nl; ++p)
      if (e(a, p) != 0.0) column.push_back(p), value.push_back(e(a, p));
    start.push_back(static_cast<int>(column.size()));
  }
  // EK = E_c K_c, then local(a, b) = Σ_q EK(a, q) E_c(b, q) for a <= b. The innermost loops run
  // over independent sums (q, then a), so the double-double operations pipeline instead of waiting
  // on one chain of dependent additions.
  thread_local std::vector<double> ek_hi, ek_lo, acc_hi, acc_lo;  // EK column-major (na x nl)
  ek_hi.assign(static_cast<std::size_t>(na) * nl, 0.0);
  ek_lo.assign(static_cast<std::size_t>(na) * nl, 0.0);
  for (int a = 0; a < na; ++a)
    for (int s = start[a]; s < start[a + 1]; ++s) {
      const double v = value[s];
      const double* k_hi = k.hi.data() + static_cast<std::size_t>(nl) * column[s];  // K(., p) = K(p, .)
      const double* k_lo = k.lo.data() + static_cast<std::size_t>(nl) * column[s];
      for (int q = 0; q < nl; ++q) {
        const std::size_t at = static_cast<std::size_t>(q) * na + a;
        const DoubleDouble sum = DoubleDouble(ek_hi[at], ek_lo[at]) + DoubleDouble(k_hi[q], k_lo[q]) * v;
        ek_hi[at] = sum.hi, ek_lo[at] = sum.lo;
      }
    }
  local.resize(na, na);
  acc_hi.resize(na);
  acc_lo.resize(na);
  for (int b = 0; b < na; ++b) {
    std::fill_n(acc_hi.begin(), b + 1, 0.0);
    std::fill_n(acc_lo.begin(), b + 1, 0.0);
    for (int s = start[b]; s < start[b + 1]; ++s) {
      const double v = value[s];
      const double* e_hi = ek_hi.data() + static_cast<std::size_t>(na) * column[s];
      const double* e_lo = ek_lo.data() + static_cast<std::size_t>(na) * column[s];
      for (int a = 0; a <= b; ++a) {
        const DoubleDouble sum = DoubleDouble(acc_hi[a], acc_lo[a]) + DoubleDouble(e_hi[a], e_lo[a]) * v;
        acc_hi[a] = sum.hi, acc_lo[a] = sum.lo;
      }
    }
    for (int a = 0; a <= b; ++a) {
      local.hi(a, b) = local.hi(b, a) = acc_hi[a];
      local.lo(a, b) = local.lo(b, a) = acc_lo[a];
    }
  }
  same_hash.push_back({e, local});
  ++known_count;
  return true;
}

bool TMeshSpace::closed_form_element_matrix_extended(int element, BilinearForm form,
                                                     Eigen::Matrix<long double, Eigen::Dynamic, Eigen::Dynamic>& local) const {
  using MatrixL = Eigen::Matrix<long double, Eigen::Dynamic, Eigen::Dynamic>;
  const TCell& cell = mesh_.cells()[element];
  const SideIntegrals& sx = side_integrals_.at({cell.section_s, cell.x1 - cell.x0});
  const SideIntegrals& sy = side_integrals_.at({cell.section_t, cell.y1 - cell.y0});
  const long double hx = mesh_.width(element), hy = mesh_.height(element);
  // Terms c ∫ ∂x^a ∂y^b u ∂x^a' ∂y^b' v = c hx hy hx^-(a+a') hy^-(b+b') X(a, a') ⊗ Y(b, b').
  struct Term {
    int a, b, a2, b2;
    long double c;
  };
  static constexpr Term mass[] = {{0, 0, 0, 0, 1}}, laplace[] = {{1, 0, 1, 0, 1}, {0, 1, 0, 1, 1}},
                        bilaplace[] = {{2, 0, 2, 0, 1}, {2, 0, 0, 2, 1}, {0, 2, 2, 0, 1}, {0, 2, 0, 2, 1}},
                        hessian[] = {{2, 0, 2, 0, 1}, {1, 1, 1, 1, 2}, {0, 2, 0, 2, 1}};
  std::span<const Term> terms;
  switch (form) {
    case BilinearForm::mass: terms = mass; break;
    case BilinearForm::laplace: terms = laplace; break;
    case BilinearForm::bilaplace: terms = bilaplace; break;
    case BilinearForm::hessian: terms = hessian; break;
  }
  const int nx = static_cast<int>(sx.m[0].rows()), ny = static_cast<int>(sy.m[0].rows());
  thread_local MatrixL k, e, ek;  // scratch: no allocation per element
  k.setZero(nx * ny, nx * ny);    // local index i + nx j (x fastest, as the evaluator)
  for (const Term& t : terms) {
    const long double scale = t.c * hx * hy / (std::pow(hx, t.a + t.a2) * std::pow(hy, t.b + t.b2));
    const MatrixL& X = sx.m[3 * t.a + t.a2];
    const MatrixL& Y = sy.m[3 * t.b + t.b2];
    for (int j2 = 0; j2 < ny; ++j2)
      for (int i2 = 0; i2 < nx; ++i2)
        for (int j = 0; j < ny; ++j) {
          const long double yv = scale * Y(j, j2);
          for (int i = 0; i < nx; ++i) k(i + nx * j, i2 + nx * j2) += X(i, i2) * yv;
        }
  }
  e = extraction_.matrix[element].cast<long double>();
  // Small products: coefficient-based, no GEMM packing (which dominated at these sizes); the
  // result is symmetric, so the second product fills the upper triangle and mirrors it.
  ek = e.lazyProduct(k);
  const Eigen::Index na = e.rows();
  local.resize(na, na);
  for (Eigen::Index j = 0; j < na; ++j)
    for (Eigen::Index i = 0; i <= j; ++i) local(i, j) = local(j, i) = ek.row(i).dot(e.row(j));
  return true;
}

bool TMeshSpace::closed_form_element_matrix(int element, BilinearForm form, Eigen::MatrixXd& local) const {
  Eigen::Matrix<long double, Eigen::Dynamic, Eigen::Dynamic> extended;
  closed_form_element_matrix_extended(element, form, extended);
  local = extended.cast<double>();
  return true;
}

void TMeshSpace::normalize_basis() {
  // The function dual to D_s^a D_t^b p(w) has size ~ h^(a+b) of the cells around w; on strongly
  // graded (adaptive) meshes that spreads the scales of the basis over many orders of magnitude
  // and makes mass and stiffness matrices needlessly ill-conditioned. Scaling every function to
  // largest Bernstein coefficient 1 (its sup norm up to a factor, since the Bernstein basis is a
  // nonnegative partition of unity) keeps the same space with O(1) functions.
  // Row maxima per cell in parallel, their maximum per function serially (a function spans
  // several cells), then the rows rescaled in parallel.
  const int nc = static_cast<int>(extraction_.matrix.size());
  std::vector<std::size_t> first(nc + 1, 0);
  for (int c = 0; c < nc; ++c) first[c + 1] = first[c] + extraction_.dofs[c].size();
  std::vector<double> row_max(first[nc]);
#pragma omp parallel for schedule(static) if (worth_threads(nc))
  for (int c = 0; c < nc; ++c)
    for (std::size_t a = 0; a < extraction_.dofs[c].size(); ++a)
      row_max[first[c] + a] = extraction_.matrix[c].row(static_cast<Eigen::Index>(a)).cwiseAbs().maxCoeff();
  std::vector<double> scale(extraction_.dimension, 0.0);
  for (int c = 0; c < nc; ++c)
    for (std::size_t a = 0; a < extraction_.dofs[c].size(); ++a) {
      double& s = scale[extraction_.dofs[c][a]];
      s = std::max(s, row_max[first[c] + a]);
    }
#pragma omp parallel for schedule(static) if (worth_threads(nc))
  for (int c = 0; c < nc; ++c)
    for (std::size_t a = 0; a < extraction_.dofs[c].size(); ++a) {
      const double s = scale[extraction_.dofs[c][a]];
      if (s > 0.0) extraction_.matrix[c].row(static_cast<Eigen::Index>(a)) /= s;
    }
}


int non_polynomial_extra_degree(double wh) {
  // A Gauss rule exact to degree 2n + 1 + e leaves the part of B_i B_k beyond that degree, whose
  // Taylor coefficients are below (w h)^(e+1) / (e+1)! (scaled G-basis, notes §3.1); below 1e-17
  // the rule is exact to double round-off. Coarse cells keep the ceiling (8 more points per
  // direction), where that bound is 6e-12 at w h = pi/2.
  if (!(wh > 0.0)) return 0;
  for (int e = 2; e < kFullExtraDegree; e += 2) {
    double term = 1.0;  // (w h)^(e+1) / (e+1)!
    for (int k = 1; k <= e + 1; ++k) term *= wh / k;
    if (term <= 1e-17) return e;
  }
  return kFullExtraDegree;
}

std::unique_ptr<Space::Evaluator> TMeshSpace::make_evaluator() const { return std::make_unique<TMeshEvaluator>(*this); }

std::vector<std::pair<std::string, std::string>> TMeshSpace::parameters() const {
  const int nt = static_cast<int>(mesh_.vertices().size()) - mesh_.num_non_t_vertices();
  std::string sections;
  for (const SectionSpec& s : mesh_.sections()) sections += (sections.empty() ? "" : "; ") + s.description();
  return {{"section", sections},
          {"regularity", std::to_string(r_)},
          {"cells", std::to_string(mesh_.num_cells())},
          {"T-junctions", std::to_string(nt)},
          {"domain", domain_}};
}

void TMeshSpace::cell_box(int cell, Point2& lo, Point2& hi) const {
  const TCell& c = mesh_.cells()[cell];
  lo = mesh_.point(c.x0, c.y0);
  hi = mesh_.point(c.x1, c.y1);
}

RulePtr TMeshSpace::quadrature(int, int degree) const {
  degree = std::max(degree, 0) + extra_degree_;
  std::lock_guard<std::mutex> lock(rule_mutex_);
  RulePtr& r = cell_rules_[degree];
  if (!r) r = std::make_shared<const QuadratureRule>(tensor_gauss(degree));
  return r;
}

RulePtr TMeshSpace::edge_quadrature(int, int edge, int degree) const {
  degree = std::max(degree, 0) + extra_degree_;
  std::lock_guard<std::mutex> lock(rule_mutex_);
  RulePtr& r = edge_rules_[{edge, degree}];
  if (!r) r = std::make_shared<const QuadratureRule>(edge_rule(CellShape::quadrilateral, edge, gauss_legendre_for_degree(degree)));
  return r;
}

namespace {

/// Parameter of reference_edge_point on side `side` of a cell spanning [lo, hi] along that side, at
/// lattice coordinate `at`: bottom (0) and right (1) run with the coordinate, top (2) and left (3)
/// against it (counterclockwise).
double side_parameter(int side, std::int64_t lo, std::int64_t hi, std::int64_t at) {
  const double t = double(at - lo) / double(hi - lo);
  return side < 2 ? t : 1.0 - t;
}

}  // namespace

std::vector<InteriorEdge> TMeshSpace::interior_edges() const {
  std::vector<InteriorEdge> out;
  const auto& cells = mesh_.cells();
  for (auto [a, b] : side_neighbours(mesh_)) {
    const TCell &ca = cells[a], &cb = cells[b];
    InteriorEdge e;
    e.element_a = a;
    e.element_b = b;
    if (ca.x1 == cb.x0 || cb.x1 == ca.x0) {  // vertical common segment [lo, hi] in y
      const std::int64_t lo = std::max(ca.y0, cb.y0), hi = std::min(ca.y1, cb.y1);
      e.edge_a = ca.x1 == cb.x0 ? 1 : 3;
      e.edge_b = e.edge_a == 1 ? 3 : 1;
      e.a0 = side_parameter(e.edge_a, ca.y0, ca.y1, lo), e.a1 = side_parameter(e.edge_a, ca.y0, ca.y1, hi);
      e.b0 = side_parameter(e.edge_b, cb.y0, cb.y1, lo), e.b1 = side_parameter(e.edge_b, cb.y0, cb.y1, hi);
    } else {  // horizontal common segment [lo, hi] in x
      const std::int64_t lo = std::max(ca.x0, cb.x0), hi = std::min(ca.x1, cb.x1);
      e.edge_a = ca.y1 == cb.y0 ? 2 : 0;
      e.edge_b = e.edge_a == 2 ? 0 : 2;
      e.a0 = side_parameter(e.edge_a, ca.x0, ca.x1, lo), e.a1 = side_parameter(e.edge_a, ca.x0, ca.x1, hi);
      e.b0 = side_parameter(e.edge_b, cb.x0, cb.x1, lo), e.b1 = side_parameter(e.edge_b, cb.x0, cb.x1, hi);
    }
    out.push_back(e);
  }
  return out;
}

SpacePtr TMeshSpace::refined(const std::vector<int>& marked_elements) const {
  return std::make_shared<const TMeshSpace>(refine_admissibly(mesh_, marked_elements), r_, rectangular_, domain_);
}

std::vector<std::string> TMeshSpace::boundary_names() const {
  if (rectangular_) return {"left", "right", "bottom", "top"};
  return {};
}

std::vector<BoundaryEdge> TMeshSpace::boundary_edges(const std::string& name) const {
  // Local edges of the reference square: 0 bottom, 1 right, 2 top, 3 left (mesh sides alike).
  int only = -1;
  if (name == "bottom") only = 0;
  else if (name == "right") only = 1;
  else if (name == "top") only = 2;
  else if (name == "left") only = 3;
  if (name != "all" && (only < 0 || !rectangular_))
    throw InputError("unknown boundary '" + name + "' of a T-mesh space (valid: " +
                     std::string(rectangular_ ? "left, right, bottom, top, " : "") + "all)");
  std::vector<BoundaryEdge> out;
  for (int side = 0; side < 4; ++side) {
    if (only >= 0 && side != only) continue;
    for (int c = 0; c < mesh_.num_cells(); ++c)
      if (mesh_.side_on_boundary(c, side)) out.push_back({c, side});
  }
  return out;
}

}  // namespace iga
