#include "spaces/tmesh/tmesh_space.hpp"
#include "config/worth_threads.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "spaces/tmesh/tmesh_closed_forms.hpp"
#include "spaces/tmesh/tmesh_refinement.hpp"

namespace iga {

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
  std::map<std::pair<CellSideKey, CellSideKey>, int> kind_of;
  double mesh_size = 0.0, wh = 0.0;
  for (int c = 0; c < mesh_.num_cells(); ++c) {
    const TCell& cell = mesh_.cells()[c];
    const SectionSpec &sx = mesh_.sections()[cell.section_s], &sy = mesh_.sections()[cell.section_t];
    const CellSideKey kx = side_key_x(cell), ky = side_key_y(cell);
    if (!bernstein_.count(kx)) bernstein_.emplace(kx, SectionBernstein(sx, mesh_.width(c)));
    if (!bernstein_.count(ky)) bernstein_.emplace(ky, SectionBernstein(sy, mesh_.height(c)));
    const auto [it, added] = kind_of.emplace(std::make_pair(kx, ky), static_cast<int>(kinds_.size()));
    if (added) kinds_.push_back(it->first);
    cell_kind_.push_back(it->second);
    mesh_size = std::max(mesh_size, std::hypot(mesh_.width(c), mesh_.height(c)));
    // Extra degree of every rule for the largest w h of a non-polynomial section.
    if (sx.family != SectionFamily::polynomial) wh = std::max(wh, sx.w * mesh_.width(c));
    if (sy.family != SectionFamily::polynomial) wh = std::max(wh, sy.w * mesh_.height(c));
  }
  extra_degree_ = non_polynomial_extra_degree(wh);
  closed_forms_ = std::make_unique<const TMeshClosedForms>(*this);

  SpaceFacts facts;
  facts.type = "tmesh";
  const int nt = static_cast<int>(mesh_.vertices().size()) - mesh_.num_non_t_vertices();
  std::string sections;
  for (const SectionSpec& s : mesh_.sections()) sections += (sections.empty() ? "" : "; ") + s.description();
  facts.parameters = {{"section", sections},
                      {"regularity", std::to_string(r_)},
                      {"cells", std::to_string(mesh_.num_cells())},
                      {"T-junctions", std::to_string(nt)},
                      {"domain", domain_}};
  facts.dimension = extraction_.dimension;
  facts.num_elements = mesh_.num_cells();
  facts.cell_shapes = {CellShape::quadrilateral};
  facts.mesh_size = mesh_size;
  facts.degree = section().n;
  facts.continuity = r_;
  facts.affine_elements = true;
  facts.higher_derivatives = true;  // tensor products of section spaces under a diagonal scaling
  // Local edges of the reference square: 0 bottom, 1 right, 2 top, 3 left (mesh sides alike).
  const char* side_names[] = {"bottom", "right", "top", "left"};
  std::vector<BoundaryEdge> sides[4];
  for (int side = 0; side < 4; ++side)
    for (int c = 0; c < mesh_.num_cells(); ++c)
      if (mesh_.side_on_boundary(c, side)) sides[side].push_back({c, side});
  for (int side = 0; side < 4; ++side)
    facts.all_boundary_edges.insert(facts.all_boundary_edges.end(), sides[side].begin(), sides[side].end());
  if (rectangular_)
    for (int side : {3, 1, 0, 2}) facts.boundary_parts.emplace_back(side_names[side], sides[side]);
  set_facts(std::move(facts));
}

TMeshSpace::~TMeshSpace() = default;

const ClosedForms* TMeshSpace::closed_forms() const { return closed_forms_.get(); }

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

void TMeshSpace::cell_box(int cell, Point2& lo, Point2& hi) const {
  const TCell& c = mesh_.cells()[cell];
  lo = mesh_.point(c.x0, c.y0);
  hi = mesh_.point(c.x1, c.y1);
}

RulePtr TMeshSpace::quadrature(int, int degree) const { return rules_.cell(std::max(degree, 0) + extra_degree_); }

RulePtr TMeshSpace::edge_quadrature(int, int edge, int degree) const {
  return rules_.edge(edge, std::max(degree, 0) + extra_degree_);
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

SpacePtr TMeshSpace::refine(const std::vector<int>& marked_elements) const {
  return std::make_shared<const TMeshSpace>(refine_admissibly(mesh_, marked_elements), r_, rectangular_, domain_);
}

}  // namespace iga
