#include "spaces/tmesh/tmesh.hpp"

#include <algorithm>
#include <array>
#include <complex>
#include <set>
#include <stdexcept>

namespace iga {

namespace {

/// Lattice units per base cell: room for 24 dyadic refinements.
constexpr std::int64_t kBase = std::int64_t(1) << 24;

/// A cell side on a line: [lo, hi] along the line; `positive` = the cell lies on the +y / +x side.
struct Side {
  std::int64_t lo, hi;
  int cell;
  bool positive;
};

using Lines = std::map<std::int64_t, std::vector<Side>>;

bool strictly_inside(const std::vector<Side>& sides, std::int64_t a) {
  for (const Side& s : sides)
    if (s.lo < a && a < s.hi) return true;
  return false;
}

/// Some side covers the open segment (a, b) (sides never partially cover an edge segment).
bool covers(const std::vector<Side>& sides, std::int64_t a, std::int64_t b) {
  for (const Side& s : sides)
    if (s.lo <= a && b <= s.hi) return true;
  return false;
}

std::vector<std::complex<double>> roots(const SectionSpec& s) {
  std::vector<std::complex<double>> r(s.n - 1, 0.0);
  switch (s.family) {
    case SectionFamily::polynomial: r.insert(r.end(), {0.0, 0.0}); break;
    case SectionFamily::trigonometric: r.insert(r.end(), {{0.0, s.w}, {0.0, -s.w}}); break;
    case SectionFamily::hyperbolic: r.insert(r.end(), {s.w, -s.w}); break;
  }
  return r;
}

}  // namespace

int common_nonpolynomial_dimension(const std::vector<SectionSpec>& spaces) {
  std::vector<std::complex<double>> common = roots(spaces.front());
  for (size_t k = 1; k < spaces.size(); ++k) {
    std::vector<std::complex<double>> other = roots(spaces[k]), kept;
    for (const auto& z : common) {
      auto it = std::find_if(other.begin(), other.end(), [&](auto y) { return std::abs(y - z) <= 1e-12 * (1 + std::abs(z)); });
      if (it != other.end()) {
        kept.push_back(z);
        other.erase(it);
      }
    }
    common = kept;
  }
  return static_cast<int>(common.size()) - (spaces.front().n - 1);
}

TMesh::TMesh(std::vector<TCell> cells, std::vector<SectionSpec> sections, Eigen::Vector2d origin, Eigen::Vector2d unit)
    : cells_(std::move(cells)), sections_(std::move(sections)), origin_(origin), unit_(unit) {
  if (cells_.empty()) throw std::invalid_argument("a T-mesh needs at least one cell");
  bounds_[0] = bounds_[2] = INT64_MAX;
  bounds_[1] = bounds_[3] = INT64_MIN;
  for (const TCell& c : cells_) {
    if (!(c.x0 < c.x1 && c.y0 < c.y1)) throw std::invalid_argument("T-mesh cell with empty interior");
    if (c.section_s < 0 || c.section_t < 0 || c.section_s >= int(sections_.size()) || c.section_t >= int(sections_.size()))
      throw std::invalid_argument("T-mesh cell refers to an unknown section space");
    bounds_[0] = std::min(bounds_[0], c.x0);
    bounds_[1] = std::max(bounds_[1], c.x1);
    bounds_[2] = std::min(bounds_[2], c.y0);
    bounds_[3] = std::max(bounds_[3], c.y1);
  }
  build_topology();
}

TMesh TMesh::rectangle(Eigen::Vector2d lo, Eigen::Vector2d hi, int nx, int ny, const SectionSpec& section) {
  std::vector<TCell> cells;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) cells.push_back({i * kBase, (i + 1) * kBase, j * kBase, (j + 1) * kBase, 0, 0});
  const Eigen::Vector2d unit((hi.x() - lo.x()) / (nx * double(kBase)), (hi.y() - lo.y()) / (ny * double(kBase)));
  return TMesh(std::move(cells), {section}, lo, unit);
}

TMesh TMesh::l_shape(Eigen::Vector2d lo, Eigen::Vector2d hi, int nx, int ny, const SectionSpec& section) {
  if (nx % 2 || ny % 2) throw std::invalid_argument("an L-shape grid needs even element counts");
  std::vector<TCell> cells;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      if (i < nx / 2 || j < ny / 2) cells.push_back({i * kBase, (i + 1) * kBase, j * kBase, (j + 1) * kBase, 0, 0});
  const Eigen::Vector2d unit((hi.x() - lo.x()) / (nx * double(kBase)), (hi.y() - lo.y()) / (ny * double(kBase)));
  return TMesh(std::move(cells), {section}, lo, unit);
}

TMesh TMesh::refined(const std::vector<int>& which) const {
  std::vector<char> split(cells_.size(), 0);
  for (int c : which) split.at(c) = 1;
  std::vector<TCell> out;
  for (size_t k = 0; k < cells_.size(); ++k) {
    const TCell& c = cells_[k];
    if (!split[k]) {
      out.push_back(c);
      continue;
    }
    if ((c.x1 - c.x0) % 2 || (c.y1 - c.y0) % 2) throw std::invalid_argument("T-mesh refined beyond its lattice");
    const std::int64_t xm = (c.x0 + c.x1) / 2, ym = (c.y0 + c.y1) / 2;
    for (auto [a, b, p, q] : {std::array<std::int64_t, 4>{c.x0, xm, c.y0, ym}, {xm, c.x1, c.y0, ym}, {c.x0, xm, ym, c.y1},
                              {xm, c.x1, ym, c.y1}})
      out.push_back({a, b, p, q, c.section_s, c.section_t});
  }
  return TMesh(std::move(out), sections_, origin_, unit_);
}

TMesh TMesh::refined_uniformly() const {
  std::vector<int> all(cells_.size());
  for (size_t k = 0; k < all.size(); ++k) all[k] = static_cast<int>(k);
  return refined(all);
}

int TMesh::vertex_at(std::int64_t x, std::int64_t y) const {
  auto it = vertex_id_.find({x, y});
  return it == vertex_id_.end() ? -1 : it->second;
}

int TMesh::num_non_t_vertices() const {
  int n = 0;
  for (const TVertex& v : vertices_) n += v.t_junction ? 0 : 1;
  return n;
}

void TMesh::build_topology() {
  const int nc = num_cells();
  // 1. Vertices: all cell corners, and the sides on each line.
  Lines hlines, vlines;
  corner_.assign(4 * nc, -1);
  for (int k = 0; k < nc; ++k) {
    const TCell& c = cells_[k];
    const std::int64_t xs[4] = {c.x0, c.x1, c.x1, c.x0}, ys[4] = {c.y0, c.y0, c.y1, c.y1};
    for (int j = 0; j < 4; ++j) {
      auto [it, fresh] = vertex_id_.try_emplace({xs[j], ys[j]}, static_cast<int>(vertices_.size()));
      if (fresh) vertices_.push_back({xs[j], ys[j]});
      corner_[4 * k + j] = it->second;
    }
    hlines[c.y0].push_back({c.x0, c.x1, k, true});
    hlines[c.y1].push_back({c.x0, c.x1, k, false});
    vlines[c.x0].push_back({c.y0, c.y1, k, true});
    vlines[c.x1].push_back({c.y0, c.y1, k, false});
  }
  // Overlap check: sweep over cells sorted by x0.
  {
    std::vector<int> order(nc);
    for (int k = 0; k < nc; ++k) order[k] = k;
    std::sort(order.begin(), order.end(), [&](int a, int b) { return cells_[a].x0 < cells_[b].x0; });
    for (int a = 0; a < nc; ++a)
      for (int b = a + 1; b < nc && cells_[order[b]].x0 < cells_[order[a]].x1; ++b) {
        const TCell &p = cells_[order[a]], &q = cells_[order[b]];
        if (std::max(p.y0, q.y0) < std::min(p.y1, q.y1)) throw std::invalid_argument("T-mesh cells overlap");
      }
  }

  // 2. T-junctions (corrected rule), covered quadrants, boundary, regularity.
  for (TVertex& v : vertices_) {
    const std::vector<Side>& hs = hlines[v.y];
    const std::vector<Side>& vs = vlines[v.x];
    v.t_junction = strictly_inside(hs, v.x) || strictly_inside(vs, v.y);
    // Quadrants NE, NW, SW, SE covered near v.
    bool q[4] = {false, false, false, false};
    for (const Side& s : hs) {
      if (s.lo > v.x || v.x > s.hi) continue;
      if (s.positive) {
        if (v.x < s.hi) q[0] = true;
        if (v.x > s.lo) q[1] = true;
      } else {
        if (v.x > s.lo) q[2] = true;
        if (v.x < s.hi) q[3] = true;
      }
    }
    // A vertex inside a vertical side has that cell on both of its quadrants on that side.
    for (const Side& s : vs)
      if (s.lo < v.y && v.y < s.hi) {
        if (s.positive) q[0] = q[3] = true;
        else q[1] = q[2] = true;
      }
    const int covered = q[0] + q[1] + q[2] + q[3];
    v.boundary = covered < 4;
    // Regular: the covered quadrants form one cyclic run.
    int runs = 0;
    for (int k = 0; k < 4; ++k) runs += (q[k] && !q[(k + 3) % 4]) ? 1 : 0;
    if (covered < 4 && runs > 1 && problem_.empty()) {
      const Eigen::Vector2d p = point(v.x, v.y);
      problem_ = "not regular: the cells at vertex (" + std::to_string(p.x()) + ", " + std::to_string(p.y()) +
                 ") meet only at that corner";
    }
  }

  // 3. Composite edges, line by line.
  std::map<std::int64_t, std::vector<std::int64_t>> on_h, on_v;  // line -> coordinates of vertices on it
  for (const TVertex& v : vertices_) {
    on_h[v.y].push_back(v.x);
    on_v[v.x].push_back(v.y);
  }
  side_edge_.assign(4 * nc, -1);
  side_boundary_.assign(4 * nc, 0);
  for (int dir = 0; dir < 2; ++dir) {
    const bool horizontal = dir == 0;
    Lines& lines = horizontal ? hlines : vlines;
    auto& on = horizontal ? on_h : on_v;
    for (auto& [line, sides] : lines) {
      std::vector<std::int64_t>& xs = on[line];
      std::sort(xs.begin(), xs.end());
      auto vid = [&](std::int64_t a) { return horizontal ? vertex_id_.at({a, line}) : vertex_id_.at({line, a}); };
      size_t i = 0;
      while (i + 1 < xs.size()) {
        if (!covers(sides, xs[i], xs[i + 1])) {
          ++i;
          continue;
        }
        size_t j = i + 1;
        while (j + 1 < xs.size() && strictly_inside(sides, xs[j])) ++j;
        CompositeEdge e;
        e.horizontal = horizontal;
        e.line = line;
        e.lo = xs[i];
        e.hi = xs[j];
        e.v_lo = vid(xs[i]);
        e.v_hi = vid(xs[j]);
        const int id = static_cast<int>(edges_.size());
        for (size_t k = i + 1; k < j; ++k) {
          e.t_junctions.push_back(vid(xs[k]));
          vertices_[vid(xs[k])].host_edge = id;
        }
        std::vector<SectionSpec> along;
        for (const Side& s : sides)
          if (std::max(s.lo, e.lo) < std::min(s.hi, e.hi)) {
            e.cells.push_back(s.cell);
            const TCell& c = cells_[s.cell];
            along.push_back(sections_[horizontal ? c.section_s : c.section_t]);
            // Side index: bottom 0 (cell above a horizontal line), top 2, left 3, right 1.
            const int side = horizontal ? (s.positive ? 0 : 2) : (s.positive ? 3 : 1);
            side_edge_[4 * s.cell + side] = id;
            // On the boundary when nothing faces it from the other side.
            std::int64_t faced = 0;
            for (const Side& o : sides)
              if (o.positive != s.positive) faced += std::max<std::int64_t>(0, std::min(o.hi, s.hi) - std::max(o.lo, s.lo));
            side_boundary_[4 * s.cell + side] = faced == 0 ? 1 : 0;
            if (faced > 0 && faced < s.hi - s.lo) partial_boundary_ = true;
          }
        e.d = common_nonpolynomial_dimension(along);
        edges_.push_back(std::move(e));
        i = j;
      }
    }
  }
  for (int k = 0; k < 4 * nc; ++k)
    if (side_edge_[k] < 0) throw std::logic_error("T-mesh: a cell side lies in no composite edge");

  // 4. Dependencies and a topological order (Kahn); a leftover edge means a cycle.
  for (CompositeEdge& e : edges_)
    for (int v : {e.v_lo, e.v_hi})
      if (vertices_[v].t_junction) e.deps.push_back(vertices_[v].host_edge);
  const int ne = static_cast<int>(edges_.size());
  std::vector<int> indeg(ne, 0), chain(ne, 0);
  std::vector<std::vector<int>> users(ne);
  for (int k = 0; k < ne; ++k)
    for (int d : edges_[k].deps) {
      ++indeg[k];
      users[d].push_back(k);
    }
  std::vector<int> ready;
  for (int k = 0; k < ne; ++k)
    if (indeg[k] == 0) ready.push_back(k);
  edge_order_.clear();
  while (!ready.empty()) {
    const int k = ready.back();
    ready.pop_back();
    edge_order_.push_back(k);
    for (int u : users[k]) {
      chain[u] = std::max(chain[u], chain[k] + 1);
      if (--indeg[u] == 0) ready.push_back(u);
    }
  }
  longest_chain_ = ne ? *std::max_element(chain.begin(), chain.end()) : 0;
  if (static_cast<int>(edge_order_.size()) != ne) {
    edge_order_.clear();
    if (problem_.empty()) problem_ = "the T-junctions form a cycle (each extends a composite edge ending at the next)";
  }
}

int TMesh::dimension_formula(int r1, int r2) const {
  const int n1 = sections_[cells_[0].section_s].n, n2 = sections_[cells_[0].section_t].n;
  int dim = (r1 + 1) * (r2 + 1) * num_non_t_vertices() + (n1 - 2 * r1 - 1) * (n2 - 2 * r2 - 1) * num_cells();
  for (const CompositeEdge& e : edges_)
    dim += e.horizontal ? (r2 + 1) * (n1 - 2 * r1 - 3 + e.d) : (r1 + 1) * (n2 - 2 * r2 - 3 + e.d);
  return dim;
}

}  // namespace iga
