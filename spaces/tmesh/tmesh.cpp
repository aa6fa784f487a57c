#include "spaces/tmesh/tmesh.hpp"

#include <algorithm>
#include <array>
#include <climits>
#include <complex>
#include <map>
#include <span>
#include <tuple>
#include <stdexcept>

namespace iga {

namespace {

/// A cell's section pair must name two of the `count` section spaces.
void check_section_indices(int s, int t, std::size_t count) {
  if (s < 0 || t < 0 || s >= int(count) || t >= int(count))
    throw std::invalid_argument("T-mesh cell refers to an unknown section space");
}

/// Lattice units per base cell: room for 24 dyadic refinements.
constexpr std::int64_t kBase = std::int64_t(1) << 24;

/// A cell side on a line: [lo, hi] along the line.
struct Side {
  std::int64_t lo, hi;
  int cell;
};

/// The cell sides on one line, split by the side of the line their cell lies on (+y / +x: `pos`).
/// Cells do not overlap, so each list is disjoint; sorted by lo (hence by hi), which turns every
/// query below into a binary search instead of a scan of the line.
struct Line {
  std::int64_t at = 0;
  std::vector<Side> pos, neg;
};

/// First side of a sorted disjoint list with hi > a (hi >= a when `inclusive`).
std::vector<Side>::const_iterator first_reaching(const std::vector<Side>& sides, std::int64_t a, bool inclusive) {
  return std::partition_point(sides.begin(), sides.end(),
                              [&](const Side& s) { return inclusive ? s.hi < a : s.hi <= a; });
}

bool strictly_inside(const std::vector<Side>& sides, std::int64_t a) {
  const auto it = first_reaching(sides, a, false);
  return it != sides.end() && it->lo < a;
}

bool strictly_inside(const Line& line, std::int64_t a) { return strictly_inside(line.pos, a) || strictly_inside(line.neg, a); }

/// Some side covers the open segment (a, b) (sides never partially cover an edge segment).
bool covers(const std::vector<Side>& sides, std::int64_t a, std::int64_t b) {
  const auto it = first_reaching(sides, b, true);
  return it != sides.end() && it->lo <= a;
}

bool covers(const Line& line, std::int64_t a, std::int64_t b) { return covers(line.pos, a, b) || covers(line.neg, a, b); }

/// Lines of one direction, sorted by position; `line_of` finds one by binary search. Horizontal
/// lines y = c carry bottom (pos) and top (neg) sides, vertical lines x = c left (pos) and right (neg).
std::vector<Line> make_lines(const std::vector<TCell>& cells, bool horizontal) {
  std::vector<std::pair<std::int64_t, Side>> pos, neg;
  pos.reserve(cells.size());
  neg.reserve(cells.size());
  for (int k = 0; k < static_cast<int>(cells.size()); ++k) {
    const TCell& c = cells[k];
    const Side side = horizontal ? Side{c.x0, c.x1, k} : Side{c.y0, c.y1, k};
    pos.push_back({horizontal ? c.y0 : c.x0, side});
    neg.push_back({horizontal ? c.y1 : c.x1, side});
  }
  auto by_line = [](const auto& a, const auto& b) { return a.first != b.first ? a.first < b.first : a.second.lo < b.second.lo; };
  std::sort(pos.begin(), pos.end(), by_line);
  std::sort(neg.begin(), neg.end(), by_line);
  std::vector<Line> lines;
  std::size_t i = 0, j = 0;
  while (i < pos.size() || j < neg.size()) {
    const std::int64_t at = j == neg.size() || (i < pos.size() && pos[i].first < neg[j].first) ? pos[i].first : neg[j].first;
    Line& line = lines.emplace_back();
    line.at = at;
    for (; i < pos.size() && pos[i].first == at; ++i) line.pos.push_back(pos[i].second);
    for (; j < neg.size() && neg[j].first == at; ++j) line.neg.push_back(neg[j].second);
  }
  return lines;
}

const Line& line_of(const std::vector<Line>& lines, std::int64_t at) {
  const auto it = std::partition_point(lines.begin(), lines.end(), [&](const Line& l) { return l.at < at; });
  return *it;  // every vertex is a cell corner, so both of its lines carry sides
}

/// Calls f(side) for the sides of a sorted disjoint list that overlap (lo, hi) in positive length.
template <class F>
void for_overlapping(const std::vector<Side>& sides, std::int64_t lo, std::int64_t hi, F&& f) {
  for (auto it = first_reaching(sides, lo, false); it != sides.end() && it->lo < hi; ++it) f(*it);
}

/// Throws when two cells overlap: a sweep over x keeps the y-intervals of the cells crossing the
/// sweep line, which are disjoint exactly when no two of those cells overlap.
void check_no_overlap(const std::vector<TCell>& cells) {
  const int nc = static_cast<int>(cells.size());
  std::vector<int> by_start(nc), by_end(nc);
  for (int k = 0; k < nc; ++k) by_start[k] = by_end[k] = k;
  std::sort(by_start.begin(), by_start.end(), [&](int a, int b) { return cells[a].x0 < cells[b].x0; });
  std::sort(by_end.begin(), by_end.end(), [&](int a, int b) { return cells[a].x1 < cells[b].x1; });
  std::map<std::int64_t, std::int64_t> active;  // y0 -> y1 of the cells crossing the sweep line
  std::size_t e = 0;
  for (int k : by_start) {
    const TCell& c = cells[k];
    for (; e < by_end.size() && cells[by_end[e]].x1 <= c.x0; ++e) {
      const auto it = active.find(cells[by_end[e]].y0);
      if (it != active.end() && it->second == cells[by_end[e]].y1) active.erase(it);
    }
    auto next = active.lower_bound(c.y0);
    if (next != active.end() && next->first < c.y1) throw std::invalid_argument("T-mesh cells overlap");
    if (next != active.begin() && std::prev(next)->second > c.y0) throw std::invalid_argument("T-mesh cells overlap");
    active.emplace_hint(next, c.y0, c.y1);
  }
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

/// d_e of the notes: dim of the intersection of the section spaces (root multisets) minus (n-1).
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

}  // namespace

TMesh::TMesh(std::vector<TCell> cells, std::vector<SectionSpec> sections, Eigen::Vector2d origin, Eigen::Vector2d unit)
    : cells_(std::move(cells)), sections_(std::move(sections)), origin_(origin), unit_(unit) {
  if (cells_.empty()) throw std::invalid_argument("a T-mesh needs at least one cell");
  bounds_[0] = bounds_[2] = INT64_MAX;
  bounds_[1] = bounds_[3] = INT64_MIN;
  for (const TCell& c : cells_) {
    if (!(c.x0 < c.x1 && c.y0 < c.y1)) throw std::invalid_argument("T-mesh cell with empty interior");
    check_section_indices(c.section_s, c.section_t, sections_.size());
    bounds_[0] = std::min(bounds_[0], c.x0);
    bounds_[1] = std::max(bounds_[1], c.x1);
    bounds_[2] = std::min(bounds_[2], c.y0);
    bounds_[3] = std::max(bounds_[3], c.y1);
  }
  build_topology();
}

namespace {

/// The (nx x ny) grid of equal cells on [lo, hi], the cells (i, j) that `keep` accepts, one section.
template <class Keep>
TMesh grid(Eigen::Vector2d lo, Eigen::Vector2d hi, int nx, int ny, const SectionSpec& section, Keep keep) {
  std::vector<TCell> cells;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      if (keep(i, j)) cells.push_back({i * kBase, (i + 1) * kBase, j * kBase, (j + 1) * kBase, 0, 0});
  const Eigen::Vector2d unit((hi.x() - lo.x()) / (nx * double(kBase)), (hi.y() - lo.y()) / (ny * double(kBase)));
  return TMesh(std::move(cells), {section}, lo, unit);
}

}  // namespace

TMesh TMesh::rectangle(Eigen::Vector2d lo, Eigen::Vector2d hi, int nx, int ny, const SectionSpec& section) {
  return grid(lo, hi, nx, ny, section, [](int, int) { return true; });
}

TMesh TMesh::l_shape(Eigen::Vector2d lo, Eigen::Vector2d hi, int nx, int ny, const SectionSpec& section) {
  if (nx % 2 || ny % 2) throw std::invalid_argument("an L-shape grid needs even element counts");
  return grid(lo, hi, nx, ny, section, [&](int i, int j) { return i < nx / 2 || j < ny / 2; });
}

std::vector<TCell> TMesh::split_cells(const std::vector<TCell>& cells, const std::vector<int>& which) {
  std::vector<char> split(cells.size(), 0);
  for (int c : which) split.at(c) = 1;
  std::vector<TCell> out;
  out.reserve(cells.size() + 3 * which.size());
  for (size_t k = 0; k < cells.size(); ++k) {
    const TCell& c = cells[k];
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
  return out;
}

TMesh TMesh::refined(const std::vector<int>& which) const {
  return TMesh(split_cells(cells_, which), sections_, origin_, unit_);
}

TMesh TMesh::refined_uniformly() const {
  std::vector<int> all(cells_.size());
  for (size_t k = 0; k < all.size(); ++k) all[k] = static_cast<int>(k);
  return refined(all);
}

int TMesh::vertex_at(std::int64_t x, std::int64_t y) const {
  const auto it = std::lower_bound(vertex_index_.begin(), vertex_index_.end(), std::make_tuple(x, y, INT_MIN));
  return it != vertex_index_.end() && std::get<0>(*it) == x && std::get<1>(*it) == y ? std::get<2>(*it) : -1;
}

int TMesh::num_non_t_vertices() const {
  int n = 0;
  for (const TVertex& v : vertices_) n += v.t_junction ? 0 : 1;
  return n;
}

void TMesh::build_topology() {
  const int nc = num_cells();
  check_no_overlap(cells_);
  // 1. Vertices: all cell corners, numbered in order of first appearance (cell by cell, corners
  // counterclockwise), which the DOF numbering follows.
  {
    struct At {
      std::int64_t x, y;
      int slot;  // 4 cell + corner
    };
    std::vector<At> all(4 * static_cast<std::size_t>(nc));
    for (int k = 0; k < nc; ++k) {
      const TCell& c = cells_[k];
      const std::int64_t xs[4] = {c.x0, c.x1, c.x1, c.x0}, ys[4] = {c.y0, c.y0, c.y1, c.y1};
      for (int j = 0; j < 4; ++j) all[4 * k + j] = {xs[j], ys[j], 4 * k + j};
    }
    std::sort(all.begin(), all.end(),
              [](const At& a, const At& b) { return a.x != b.x ? a.x < b.x : a.y != b.y ? a.y < b.y : a.slot < b.slot; });
    std::vector<std::pair<int, std::size_t>> first;  // (first slot, start in `all`) per distinct point
    for (std::size_t i = 0; i < all.size(); ++i)
      if (i == 0 || all[i].x != all[i - 1].x || all[i].y != all[i - 1].y) first.emplace_back(all[i].slot, i);
    std::sort(first.begin(), first.end());
    vertices_.resize(first.size());
    vertex_index_.resize(first.size());
    for (std::size_t v = 0; v < first.size(); ++v) {
      const std::size_t i0 = first[v].second;
      vertices_[v].x = all[i0].x;
      vertices_[v].y = all[i0].y;
    }
    for (std::size_t v = 0; v < vertices_.size(); ++v) vertex_index_[v] = {vertices_[v].x, vertices_[v].y, static_cast<int>(v)};
    std::sort(vertex_index_.begin(), vertex_index_.end());
  }
  // The sides on each line.
  const std::vector<Line> hlines = make_lines(cells_, true), vlines = make_lines(cells_, false);

  // 2. T-junctions (corrected rule), covered quadrants, boundary, regularity.
  for (TVertex& v : vertices_) {
    const Line& hs = line_of(hlines, v.y);
    const Line& vs = line_of(vlines, v.x);
    v.t_junction = strictly_inside(hs, v.x) || strictly_inside(vs, v.y);
    // Quadrants NE, NW, SW, SE covered near v.
    bool q[4] = {false, false, false, false};
    for (auto it = first_reaching(hs.pos, v.x, true); it != hs.pos.end() && it->lo <= v.x; ++it) {
      if (v.x < it->hi) q[0] = true;
      if (v.x > it->lo) q[1] = true;
    }
    for (auto it = first_reaching(hs.neg, v.x, true); it != hs.neg.end() && it->lo <= v.x; ++it) {
      if (v.x > it->lo) q[2] = true;
      if (v.x < it->hi) q[3] = true;
    }
    // A vertex inside a vertical side has that cell on both of its quadrants on that side.
    if (strictly_inside(vs.pos, v.y)) q[0] = q[3] = true;
    if (strictly_inside(vs.neg, v.y)) q[1] = q[2] = true;
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
  struct OnLine {
    std::int64_t line, at;
    int vertex;
    bool operator<(const OnLine& o) const { return line != o.line ? line < o.line : at < o.at; }
  };
  std::vector<OnLine> on_h(vertices_.size()), on_v(vertices_.size());  // vertices by line, then along it
  for (std::size_t v = 0; v < vertices_.size(); ++v) {
    on_h[v] = {vertices_[v].y, vertices_[v].x, static_cast<int>(v)};
    on_v[v] = {vertices_[v].x, vertices_[v].y, static_cast<int>(v)};
  }
  std::sort(on_h.begin(), on_h.end());
  std::sort(on_v.begin(), on_v.end());
  side_edge_.assign(4 * nc, -1);
  side_boundary_.assign(4 * nc, 0);
  for (int dir = 0; dir < 2; ++dir) {
    const bool horizontal = dir == 0;
    const std::vector<Line>& lines = horizontal ? hlines : vlines;
    const std::vector<OnLine>& on = horizontal ? on_h : on_v;
    auto from = on.begin();
    for (const Line& line : lines) {
      from = std::lower_bound(from, on.end(), OnLine{line.at, INT64_MIN, -1});
      const auto to = std::upper_bound(from, on.end(), OnLine{line.at, INT64_MAX, -1});
      const std::span<const OnLine> xs(from, to);
      size_t i = 0;
      while (i + 1 < xs.size()) {
        if (!covers(line, xs[i].at, xs[i + 1].at)) {
          ++i;
          continue;
        }
        size_t j = i + 1;
        while (j + 1 < xs.size() && strictly_inside(line, xs[j].at)) ++j;
        CompositeEdge e;
        e.horizontal = horizontal;
        e.line = line.at;
        e.lo = xs[i].at;
        e.hi = xs[j].at;
        e.v_lo = xs[i].vertex;
        e.v_hi = xs[j].vertex;
        const int id = static_cast<int>(edges_.size());
        for (size_t k = i + 1; k < j; ++k) {
          e.t_junctions.push_back(xs[k].vertex);
          vertices_[xs[k].vertex].host_edge = id;
        }
        for (const bool positive : {true, false}) {
          const std::vector<Side>& mine = positive ? line.pos : line.neg;
          const std::vector<Side>& other = positive ? line.neg : line.pos;
          for_overlapping(mine, e.lo, e.hi, [&](const Side& s) {
            e.cells.push_back(s.cell);
            // Side index: bottom 0 (cell above a horizontal line), top 2, left 3, right 1.
            const int side = horizontal ? (positive ? 0 : 2) : (positive ? 3 : 1);
            side_edge_[4 * s.cell + side] = id;
            // On the boundary when nothing faces it from the other side.
            std::int64_t faced = 0;
            for_overlapping(other, s.lo, s.hi, [&](const Side& o) { faced += std::min(o.hi, s.hi) - std::max(o.lo, s.lo); });
            side_boundary_[4 * s.cell + side] = faced == 0 ? 1 : 0;
            if (faced > 0 && faced < s.hi - s.lo) partial_boundary_ = true;
          });
        }
        std::sort(e.cells.begin(), e.cells.end());  // Delta_e in cell order
        edges_.push_back(std::move(e));
        i = j;
      }
      from = to;
    }
  }
  for (int k = 0; k < 4 * nc; ++k)
    if (side_edge_[k] < 0) throw std::logic_error("T-mesh: a cell side lies in no composite edge");
  assign_edge_dimensions();

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

void TMesh::assign_edge_dimensions() {
  // d_e of the edges along one section space (the usual case), computed once per section.
  std::vector<int> single_d(sections_.size(), -1);
  std::vector<SectionSpec> along;
  for (CompositeEdge& e : edges_) {
    const auto section_along = [&](int cell) { return e.horizontal ? cells_[cell].section_s : cells_[cell].section_t; };
    const int s0 = section_along(e.cells.front());
    if (std::all_of(e.cells.begin(), e.cells.end(), [&](int c) { return section_along(c) == s0; })) {
      if (single_d[s0] < 0) single_d[s0] = common_nonpolynomial_dimension({sections_[s0]});
      e.d = single_d[s0];
    } else {
      along.clear();
      for (int c : e.cells) along.push_back(sections_[section_along(c)]);
      e.d = common_nonpolynomial_dimension(along);
    }
  }
}

TMesh TMesh::with_sections(const std::vector<std::array<int, 2>>& cell_sections, std::vector<SectionSpec> sections) const {
  if (cell_sections.size() != cells_.size()) throw std::invalid_argument("T-mesh sections: one pair per cell expected");
  TMesh out = *this;
  out.sections_ = std::move(sections);
  for (std::size_t c = 0; c < cells_.size(); ++c) {
    const auto [s, t] = cell_sections[c];
    check_section_indices(s, t, out.sections_.size());
    out.cells_[c].section_s = s;
    out.cells_[c].section_t = t;
  }
  out.assign_edge_dimensions();  // the only part of the topology the sections enter
  return out;
}

int TMesh::dimension_formula(int r1, int r2) const {
  const int n1 = sections_[cells_[0].section_s].n, n2 = sections_[cells_[0].section_t].n;
  int dim = (r1 + 1) * (r2 + 1) * num_non_t_vertices() + (n1 - 2 * r1 - 1) * (n2 - 2 * r2 - 1) * num_cells();
  for (const CompositeEdge& e : edges_)
    dim += e.horizontal ? (r2 + 1) * (n1 - 2 * r1 - 3 + e.d) : (r1 + 1) * (n2 - 2 * r2 - 3 + e.d);
  return dim;
}

}  // namespace iga
