#include "spaces/tmesh/tmesh_space.hpp"

#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "solver/errors.hpp"
#include "spaces/push_forward.hpp"
#include "spaces/tmesh/tmesh_refinement.hpp"

namespace iga {

// ---------------------------------------------------------------------------------------------
// Evaluator: Bernstein tables per (rule, cell size), then per cell only E_c times the tensor table.

class TMeshSpace::TMeshEvaluator final : public Space::Evaluator {
 public:
  explicit TMeshEvaluator(const TMeshSpace& space) : space_(space) {}
  void evaluate(int element, const QuadratureRule& rule, unsigned flags, PointValues& out) override;

 private:
  /// Reference derivatives (orders 0..2) of the Bernstein basis along x and y: (n+1) x q each.
  struct Tables {
    std::vector<Point2> points;
    Eigen::MatrixXd bx[3], by[3];
  };
  const Tables& tables(const QuadratureRule& rule, const TCell& cell);

  const TMeshSpace& space_;
  std::map<std::tuple<const QuadratureRule*, int, int, std::int64_t, std::int64_t>, Tables> cache_;
  Eigen::MatrixXd local_[6];
  ReferenceDerivatives ref_;
  std::vector<GeometryJet> jets_;
};

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
}

void TMeshSpace::normalize_basis() {
  // The function dual to D_s^a D_t^b p(w) has size ~ h^(a+b) of the cells around w; on strongly
  // graded (adaptive) meshes that spreads the scales of the basis over many orders of magnitude
  // and makes mass and stiffness matrices needlessly ill-conditioned. Scaling every function to
  // largest Bernstein coefficient 1 (its sup norm up to a factor, since the Bernstein basis is a
  // nonnegative partition of unity) keeps the same space with O(1) functions.
  std::vector<double> scale(extraction_.dimension, 0.0);
  for (std::size_t c = 0; c < extraction_.matrix.size(); ++c)
    for (std::size_t a = 0; a < extraction_.dofs[c].size(); ++a) {
      double& s = scale[extraction_.dofs[c][a]];
      s = std::max(s, extraction_.matrix[c].row(static_cast<Eigen::Index>(a)).cwiseAbs().maxCoeff());
    }
  for (std::size_t c = 0; c < extraction_.matrix.size(); ++c)
    for (std::size_t a = 0; a < extraction_.dofs[c].size(); ++a) {
      const double s = scale[extraction_.dofs[c][a]];
      if (s > 0.0) extraction_.matrix[c].row(static_cast<Eigen::Index>(a)) /= s;
    }
}

int TMeshSpace::extra_points() const {
  for (const SectionSpec& s : mesh_.sections())
    if (s.family != SectionFamily::polynomial) return 16;
  return 0;
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
  degree = std::max(degree, 0) + extra_points();
  std::lock_guard<std::mutex> lock(rule_mutex_);
  RulePtr& r = cell_rules_[degree];
  if (!r) r = std::make_shared<const QuadratureRule>(tensor_gauss(degree));
  return r;
}

RulePtr TMeshSpace::edge_quadrature(int, int edge, int degree) const {
  degree = std::max(degree, 0) + extra_points();
  std::lock_guard<std::mutex> lock(rule_mutex_);
  RulePtr& r = edge_rules_[{edge, degree}];
  if (!r) r = std::make_shared<const QuadratureRule>(edge_rule(CellShape::quadrilateral, edge, gauss_legendre_for_degree(degree)));
  return r;
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
