#include "spaces/bspline/tensor_bspline_space.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "spaces/bspline/bspline_basis_1d.hpp"
#include "spaces/bspline/tensor_bernstein_tables.hpp"
#include "spaces/extracted_evaluator.hpp"

namespace iga {

namespace {

/// Every breakpoint of `geometry` must be (within round-off) a knot of `space`.
bool contains_breakpoints(const KnotVector& space, const KnotVector& geometry) {
  const std::vector<double> knots = space.breakpoints();
  for (double t : geometry.breakpoints()) {
    const auto it = std::lower_bound(knots.begin(), knots.end(), t - 1e-12);
    if (it == knots.end() || std::abs(*it - t) > 1e-12) return false;
  }
  return true;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Evaluator specialisation (element_core.hpp): Bernstein tables per rule, then per element the two
// 1D extractions (sum factorization) + geometry + push-forward.

class TensorBSplineSpace::TensorEvaluator final : public Space::Evaluator {
 public:
  explicit TensorEvaluator(const TensorBSplineSpace& space) : Space::Evaluator(space), space_(space) {}

  void evaluate(int element, const QuadratureRule& rule, unsigned flags, PointValues& out) override;
  /// u_h = Σ c_ab N_a(u) M_b(v) by sum factorization: the reference derivatives of u_h are
  /// tu_dᵀ C tv_e at each point, with no table of every active function (the error norms' path).
  void evaluate_element_function(int element, const QuadratureRule& rule, const Eigen::VectorXd& local, unsigned flags,
                                 PointValues& geometry, FunctionValues& out) override;
  /// Points and Jacobians alone, without the basis (data checks, VTK points, outlines).
  void evaluate_geometry(int element, const QuadratureRule& rule, PointValues& out) override;
  /// Σ_q w_q N_a(u_q) M_b(v_q) = (tu diag(w) tvᵀ)(a, b), by sum factorization (load vectors).
  void integrate_values(int element, const QuadratureRule& rule, const PointValues& geometry,
                        const Eigen::VectorXd& weights, Eigen::VectorXd& local) override;

 private:
  /// tu_, tv_: the element's 1D active functions and derivatives up to order nd at the points.
  void active_1d(int element, const QuadratureRule& rule, int nd);

  /// Bernstein values and derivatives (orders 0..2) at the points of one rule: (p+1) x q each.
  struct Tables {
    std::vector<Point2> points;  // copy, to detect a different rule at a reused address
    Eigen::MatrixXd bu[3], bv[3];
  };
  const Tables& tables(const QuadratureRule& rule);

  const TensorBSplineSpace& space_;
  std::map<const QuadratureRule*, Tables> cache_;
  // Scratch reused between calls.
  Eigen::MatrixXd tu_[3], tv_[3];
  ReferenceDerivatives ref_, one_;
  PointValues single_;
  std::vector<GeometryJet> jets_;
};

const TensorBSplineSpace::TensorEvaluator::Tables& TensorBSplineSpace::TensorEvaluator::tables(
    const QuadratureRule& rule) {
  auto it = cache_.find(&rule);
  if (it != cache_.end() && it->second.points == rule.points) return it->second;
  // Temporary rules could otherwise grow the cache without bound.
  if (it == cache_.end() && cache_.size() >= 64) cache_.clear();
  Tables& t = cache_[&rule];
  t.points = rule.points;
  const int pu = space_.knots_u_.degree(), pv = space_.knots_v_.degree();
  const int q = rule.size();
  for (int d = 0; d < 3; ++d) {
    t.bu[d].resize(pu + 1, q);
    t.bv[d].resize(pv + 1, q);
  }
  for (int k = 0; k < q; ++k) {
    const Eigen::MatrixXd bu = bernstein_derivatives(pu, rule.points[k].x(), 2);
    const Eigen::MatrixXd bv = bernstein_derivatives(pv, rule.points[k].y(), 2);
    for (int d = 0; d < 3; ++d) {
      t.bu[d].col(k) = bu.row(d).transpose();
      t.bv[d].col(k) = bv.row(d).transpose();
    }
  }
  return t;
}

void TensorBSplineSpace::TensorEvaluator::active_1d(int element, const QuadratureRule& rule, int nd) {
  const TensorBSplineSpace& s = space_;
  const Tables& t = tables(rule);
  const int nex = s.num_elements_u();
  const int ex = element % nex, ey = element / nex;
  // 1D active functions at the points: extraction times Bernstein tables.
  for (int d = 0; d <= nd; ++d) {
    tu_[d].noalias() = s.extraction_u_[ex] * t.bu[d];
    tv_[d].noalias() = s.extraction_v_[ey] * t.bv[d];
  }
}

void TensorBSplineSpace::TensorEvaluator::evaluate(int element, const QuadratureRule& rule, unsigned flags,
                                                   PointValues& out) {
  const TensorBSplineSpace& s = space_;
  const int pu = s.knots_u_.degree(), pv = s.knots_v_.degree();
  const int q = rule.size();
  const bool values = (flags & update_values) != 0;
  const bool grads = (flags & (update_gradients | update_hessians)) != 0;
  const bool hess = (flags & update_hessians) != 0;
  const int nd = hess ? 2 : (grads ? 1 : 0);
  active_1d(element, rule, nd);
  const int n = (pu + 1) * (pv + 1);
  if (values) ref_.value.resize(n, q);
  if (grads) {
    ref_.dxi.resize(n, q);
    ref_.deta.resize(n, q);
  }
  if (hess) {
    ref_.dxixi.resize(n, q);
    ref_.dxieta.resize(n, q);
    ref_.detaeta.resize(n, q);
  }
  for (int k = 0; k < q; ++k)
    for (int b = 0; b <= pv; ++b)
      for (int a = 0; a <= pu; ++a) {
        const int i = a + b * (pu + 1);
        if (values) ref_.value(i, k) = tu_[0](a, k) * tv_[0](b, k);
        if (grads) {
          ref_.dxi(i, k) = tu_[1](a, k) * tv_[0](b, k);
          ref_.deta(i, k) = tu_[0](a, k) * tv_[1](b, k);
        }
        if (hess) {
          ref_.dxixi(i, k) = tu_[2](a, k) * tv_[0](b, k);
          ref_.dxieta(i, k) = tu_[1](a, k) * tv_[1](b, k);
          ref_.detaeta(i, k) = tu_[0](a, k) * tv_[2](b, k);
        }
      }
  s.element_dofs(element, out.dofs);
  space_.element_jets(element, rule, hess, jets_);
  push_forward(jets_, ref_, flags, out);
}

void TensorBSplineSpace::TensorEvaluator::evaluate_element_function(int element, const QuadratureRule& rule,
                                                                    const Eigen::VectorXd& local, unsigned flags,
                                                                    PointValues& geometry, FunctionValues& out) {
  if (flags & (update_laplacian_gradient | update_bilaplacian))
    throw std::logic_error("evaluate_function: this space provides derivatives up to order 2 only");
  const TensorBSplineSpace& s = space_;
  const int pu = s.knots_u_.degree(), pv = s.knots_v_.degree();
  const bool grads = (flags & (update_gradients | update_hessians)) != 0;
  const bool hess = (flags & update_hessians) != 0;
  const int nd = hess ? 2 : (grads ? 1 : 0);
  active_1d(element, rule, nd);
  s.element_dofs(element, geometry.dofs);
  // C(a, b) = c of the active function a + b (pu + 1), the order of element_dofs.
  Eigen::MatrixXd c(pu + 1, pv + 1);
  for (int b = 0; b <= pv; ++b)
    for (int a = 0; a <= pu; ++a) c(a, b) = local(a + b * (pu + 1));
  Eigen::MatrixXd cv[3];  // C tv_d
  for (int d = 0; d <= nd; ++d) cv[d].noalias() = c * tv_[d];
  auto reference = [&](int du, int dv) -> Eigen::MatrixXd { return tu_[du].cwiseProduct(cv[dv]).colwise().sum(); };
  one_.value = reference(0, 0);
  if (grads) {
    one_.dxi = reference(1, 0);
    one_.deta = reference(0, 1);
  }
  if (hess) {
    one_.dxixi = reference(2, 0);
    one_.dxieta = reference(1, 1);
    one_.detaeta = reference(0, 2);
  }
  space_.element_jets(element, rule, hess, jets_);
  push_forward(jets_, one_, flags | update_values, single_);
  take_single_function(single_, flags, geometry, out);
}

void TensorBSplineSpace::TensorEvaluator::evaluate_geometry(int element, const QuadratureRule& rule, PointValues& out) {
  space_.element_jets(element, rule, false, jets_);
  take_geometry(jets_, out);
  space_.element_dofs(element, out.dofs);
}

void TensorBSplineSpace::TensorEvaluator::integrate_values(int element, const QuadratureRule& rule,
                                                            const PointValues& /*geometry*/,
                                                            const Eigen::VectorXd& weights, Eigen::VectorXd& local) {
  active_1d(element, rule, 0);
  const Eigen::MatrixXd sums = tu_[0] * weights.asDiagonal() * tv_[0].transpose();  // column-major: a + b (pu + 1)
  local = Eigen::Map<const Eigen::VectorXd>(sums.data(), sums.size());
}

void TensorBSplineSpace::element_jets(int element, const QuadratureRule& rule, bool hess,
                                      std::vector<GeometryJet>& jets) const {
  const TensorBSplineSpace& s = *this;
  const int nex = s.num_elements_u();
  const int ex = element % nex, ey = element / nex;
  const int q = rule.size();
  // Geometry w.r.t. reference coordinates: F(lo + h .* xi) has J diag(h) and H_kl h_k h_l.
  Point2 lo, hi;
  s.element_box(element, lo, hi);
  const Point2 h = hi - lo;
  const int gsu = s.geometry_span_u_[ex], gsv = s.geometry_span_v_[ey];
  jets.resize(q);
  if (s.geometry_->is_affine()) {
    // An affine map has one Jacobian and no curvature: evaluate it once per element.
    GeometryJet g = s.geometry_->evaluate(lo + 0.5 * h, gsu, gsv, false);
    g.jacobian.col(0) *= h.x();
    g.jacobian.col(1) *= h.y();
    for (int k = 0; k < q; ++k) {
      jets[k].jacobian = g.jacobian;
      jets[k].x = g.x + g.jacobian * (rule.points[k] - Point2(0.5, 0.5));
      jets[k].hessian_x.setZero();
      jets[k].hessian_y.setZero();
    }
    return;
  }
  for (int k = 0; k < q; ++k) {
    const Point2 uv = lo + h.cwiseProduct(rule.points[k]);
    GeometryJet g = s.geometry_->evaluate(uv, gsu, gsv, hess);
    g.jacobian.col(0) *= h.x();
    g.jacobian.col(1) *= h.y();
    if (hess) {
      const Eigen::Matrix2d scale = h * h.transpose();
      g.hessian_x = g.hessian_x.cwiseProduct(scale);
      g.hessian_y = g.hessian_y.cwiseProduct(scale);
    }
    jets[k] = g;
  }
}


/// The explicit core (element_core.hpp): the tensor Bernstein basis (local index a + b (p_u+1)),
/// C_e = C_v ⊗ C_u built per element into the core's scratch (one core per evaluator, i.e. per
/// thread), the patch map.
struct TensorBSplineSpace::Core {
  using Jet = GeometryJet;
  static constexpr bool identity = false;
  const TensorBSplineSpace& space;
  mutable Eigen::SparseMatrix<double> kron;  // local × active

  int kind(int /*e*/) const { return 0; }
  int tabulate(int /*kind*/, const std::vector<Point2>& points, int /*order*/, LocalTables& t) const {
    return tabulate_tensor_bernstein(space.knots_u_.degree(), space.knots_v_.degree(), points, t);
  }
  std::vector<int> active(int e) const {
    std::vector<int> dofs;
    space.element_dofs(e, dofs);
    return dofs;
  }
  Extraction extraction(int e) const {
    const Eigen::MatrixXd& cu = space.extraction_u_[e % space.num_elements_u()];
    const Eigen::MatrixXd& cv = space.extraction_v_[e / space.num_elements_u()];
    kron = tensor_extraction(cu, cv);
    return extraction_view(kron);
  }
  void map(int e, const QuadratureRule& rule, const LocalTables& /*t*/, int order, std::vector<Jet>& jets) const {
    space.element_jets(e, rule, order >= 2, jets);
  }
};

// ---------------------------------------------------------------------------------------------

TensorBSplineSpace::TensorBSplineSpace(std::shared_ptr<const PatchGeometry> geometry, KnotVector knots_u,
                                       KnotVector knots_v)
    : geometry_(std::move(geometry)),
      knots_u_(std::move(knots_u)),
      knots_v_(std::move(knots_v)),
      n_u_(knots_u_.num_functions()),
      n_v_(knots_v_.num_functions()) {
  if (!geometry_) throw std::invalid_argument("TensorBSplineSpace: no geometry");
  for (const KnotVector* kv : {&knots_u_, &knots_v_})
    if (kv->front() != 0.0 || kv->back() != 1.0)
      throw std::invalid_argument("TensorBSplineSpace: knot vectors must span [0,1]");
  if (!contains_breakpoints(knots_u_, geometry_->knots_u()) || !contains_breakpoints(knots_v_, geometry_->knots_v()))
    throw std::invalid_argument("TensorBSplineSpace: the knots must contain the breakpoints of the geometry");
  extraction_u_ = bezier_extractions(knots_u_);
  extraction_v_ = bezier_extractions(knots_v_);
  // The geometry piece of each element, found from its midpoint (never on a geometry knot).
  for (int mu : knots_u_.spans())
    geometry_span_u_.push_back(geometry_->knots_u().find_span(0.5 * (knots_u_[mu] + knots_u_[mu + 1])));
  for (int mu : knots_v_.spans())
    geometry_span_v_.push_back(geometry_->knots_v().find_span(0.5 * (knots_v_[mu] + knots_v_[mu + 1])));
  set_facts(make_facts());
}

std::unique_ptr<Space::Evaluator> TensorBSplineSpace::make_evaluator() const {
  return std::make_unique<TensorEvaluator>(*this);
}

std::unique_ptr<Space::Evaluator> TensorBSplineSpace::make_generic_evaluator() const {
  return std::make_unique<ExtractedEvaluator<Core>>(*this, Core{*this, {}});
}

int TensorBSplineSpace::regularity() const {
  int r = std::max(knots_u_.degree(), knots_v_.degree());
  for (const KnotVector* kv : {&knots_u_, &knots_v_}) {
    const int m = kv->max_interior_multiplicity();
    if (m > 0) r = std::min(r, kv->degree() - m);
  }
  return r;
}

void TensorBSplineSpace::element_dofs(int element, std::vector<int>& out) const {
  const int nex = num_elements_u();
  const int su = knots_u_.spans()[element % nex], sv = knots_v_.spans()[element / nex];
  const int pu = knots_u_.degree(), pv = knots_v_.degree();
  out.resize((pu + 1) * (pv + 1));
  for (int b = 0; b <= pv; ++b)
    for (int a = 0; a <= pu; ++a) out[a + b * (pu + 1)] = (su - pu + a) + (sv - pv + b) * n_u_;
}

bool TensorBSplineSpace::ExactMatrices::double_double(int element, BilinearForm form, DoubleDoubleMatrix& local) const {
  const TensorBSplineSpace& s = space_;
  if (!s.geometry_->is_affine()) return false;
  std::call_once(s.span_integrals_once_, [&s] {
    for (int mu : s.knots_u_.spans()) s.span_integrals_u_.push_back(span_integrals(s.knots_u_, mu));
    for (int mu : s.knots_v_.spans()) s.span_integrals_v_.push_back(span_integrals(s.knots_v_, mu));
  });
  const int ex = element % s.num_elements_u(), ey = element / s.num_elements_u();
  Point2 lo, hi;
  s.element_box(element, lo, hi);
  const Point2 h = hi - lo;
  GeometryJet g = s.geometry_->evaluate(lo + 0.5 * h, s.geometry_span_u_[ex], s.geometry_span_v_[ey], false);
  g.jacobian.col(0) *= h.x();
  g.jacobian.col(1) *= h.y();
  // The tensor functions N_a(s) M_b(t), ordered a + b (p_u+1); no extraction (the span integrals
  // include it). Every standard form has a closed form here.
  tensor_form_matrix(s.span_integrals_u_[ex], s.span_integrals_v_[ey],
                     affine_form_terms<DoubleDouble>(form, g.jacobian), local);
  return true;
}

void TensorBSplineSpace::element_box(int element, Point2& lo, Point2& hi) const {
  const int nex = num_elements_u();
  const int su = knots_u_.spans()[element % nex], sv = knots_v_.spans()[element / nex];
  lo = Point2(knots_u_[su], knots_v_[sv]);
  hi = Point2(knots_u_[su + 1], knots_v_[sv + 1]);
}

double TensorBSplineSpace::compute_mesh_size() const {
  // Diameter from points along the element boundary: corners for affine maps, a few more per
  // edge for curved ones (an estimate, as documented for Space::mesh_size).
  const int per_edge = geometry_->is_affine() ? 1 : 4;
  std::vector<Point2> pts(4 * per_edge);
  double h = 0.0;
  std::vector<int> elements;
  if (geometry_->is_affine()) {
    // An affine map takes every box of the same size to the same shape, and the longer mapped
    // diagonal grows with both sides: the widest column crossed with the tallest row is the
    // largest element (one element instead of all: 1 s of a 10⁶-element space, on every rank).
    int widest = 0, tallest = 0;
    Point2 lo, hi, lo2, hi2;
    for (int ex = 1; ex < num_elements_u(); ++ex) {
      element_box(ex, lo, hi);
      element_box(widest, lo2, hi2);
      if (hi.x() - lo.x() > hi2.x() - lo2.x()) widest = ex;
    }
    for (int ey = 1; ey < num_elements_v(); ++ey) {
      element_box(ey * num_elements_u(), lo, hi);
      element_box(tallest * num_elements_u(), lo2, hi2);
      if (hi.y() - lo.y() > hi2.y() - lo2.y()) tallest = ey;
    }
    elements.push_back(widest + tallest * num_elements_u());
  } else {
    elements.resize(static_cast<std::size_t>(num_elements_u()) * num_elements_v());
    std::iota(elements.begin(), elements.end(), 0);
  }
  for (int e : elements) {
    Point2 lo, hi;
    element_box(e, lo, hi);
    const int ex = e % num_elements_u(), ey = e / num_elements_u();
    for (int edge = 0; edge < 4; ++edge)
      for (int i = 0; i < per_edge; ++i) {
        const Point2 xi = reference_edge_point(CellShape::quadrilateral, edge, double(i) / per_edge);
        const Point2 uv = lo + (hi - lo).cwiseProduct(xi);
        pts[edge * per_edge + i] = geometry_->evaluate(uv, geometry_span_u_[ex], geometry_span_v_[ey], false).x;
      }
    for (size_t i = 0; i < pts.size(); ++i)
      for (size_t j = i + 1; j < pts.size(); ++j) h = std::max(h, (pts[i] - pts[j]).norm());
  }
  return h;
}

RulePtr TensorBSplineSpace::quadrature(int, int degree) const { return rules_.cell(degree); }

RulePtr TensorBSplineSpace::edge_quadrature(int, int edge, int degree) const { return rules_.edge(edge, degree); }

SpaceFacts TensorBSplineSpace::make_facts() const {
  SpaceFacts f;
  f.type = "bspline";
  const int pu = knots_u_.degree(), pv = knots_v_.degree();
  const bool interior = knots_u_.max_interior_multiplicity() > 0 || knots_v_.max_interior_multiplicity() > 0;
  f.parameters = {
      {"degree", pu == pv ? std::to_string(pu) : std::to_string(pu) + "," + std::to_string(pv)},
      {"regularity", interior ? std::to_string(regularity()) : "-"},
      {"elements", std::to_string(num_elements_u()) + "x" + std::to_string(num_elements_v())},
      {"domain", geometry_->description()},
  };
  f.dimension = n_u_ * n_v_;
  f.num_elements = num_elements_u() * num_elements_v();
  f.cell_shapes = {CellShape::quadrilateral};
  f.mesh_size = compute_mesh_size();
  f.degree = std::max(pu, pv);
  f.continuity = regularity();
  for (const KnotVector* kv : {&geometry_->knots_u(), &geometry_->knots_v()}) {
    const int m = kv->max_interior_multiplicity();
    if (m > 0) f.continuity = std::min(f.continuity, kv->degree() - m);
  }
  f.affine_elements = geometry_->is_affine();
  add_grid_boundary(f, num_elements_u(), num_elements_v(), true, true);
  return f;
}

}  // namespace iga
