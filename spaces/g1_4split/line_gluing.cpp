#include "spaces/g1_4split/line_gluing.hpp"

#include <algorithm>
#include <cmath>

namespace iga {

namespace {

constexpr double kZero = 1e-12;

bool interior_valence4(const QuadTopology& t, int v) {
  return !t.vertex_on_boundary(v) && t.vertex_faces(v) == 4 && t.vertex_edges(v).size() == 4;
}

int other_end(const QuadTopology& t, int e, int v) { return t.edge(e).g0 == v ? t.edge(e).g1 : t.edge(e).g0; }

/// One mesh line: vertices v[0..L], edges e[j] from v[j] to v[j+1].
struct GluingLine {
  std::vector<int> v, e;
  bool closed = false;
  std::vector<double> value;  ///< forward value at v[j]
  std::vector<double> mid;    ///< forward value at the middle of e[j]
};

GluingLine trace_line(const QuadTopology& t, int start, std::vector<char>& used) {
  // Walk from the start edge towards g1, then prepend the walk towards g0.
  auto walk = [&](int from, int edge, std::vector<int>& vs, std::vector<int>& es) {
    int v = other_end(t, edge, from), e = edge;
    while (interior_valence4(t, v)) {
      const int next = opposite_edge(t, v, e);
      if (next == start) return true;  // closed
      if (used[next]) return false;    // cannot happen (opposite is an involution); never loop
      es.push_back(next);
      used[next] = 1;
      v = other_end(t, next, v);
      vs.push_back(v);
      e = next;
    }
    return false;
  };
  GluingLine line;
  used[start] = 1;
  std::vector<int> fv{t.edge(start).g1}, fe;
  line.closed = walk(t.edge(start).g0, start, fv, fe);
  std::vector<int> bv{t.edge(start).g0}, be;
  if (!line.closed) walk(t.edge(start).g1, start, bv, be);
  // bv = g0, then away from it; reversed it leads up to g0.
  line.v.assign(bv.rbegin(), bv.rend());
  line.e.assign(be.rbegin(), be.rend());
  line.e.push_back(start);
  line.v.insert(line.v.end(), fv.begin(), fv.end());
  line.e.insert(line.e.end(), fe.begin(), fe.end());
  // Closed: the last vertex is the first again (v has L + 1 entries either way).
  return line;
}

}  // namespace

int opposite_edge(const QuadTopology& t, int v, int edge) {
  if (!interior_valence4(t, v)) return -1;
  std::vector<int> adjacent{edge};
  for (const auto& [f, c] : t.vertex_corners(v)) {
    const int a = t.face_edge(f, c), b = t.face_edge(f, (c + 3) % 4);
    if (a == edge) adjacent.push_back(b);
    if (b == edge) adjacent.push_back(a);
  }
  for (int e : t.vertex_edges(v))
    if (std::find(adjacent.begin(), adjacent.end(), e) == adjacent.end()) return e;
  return -1;
}

std::vector<SplitGluing> line_gluing(const QuadTopology& t, const std::vector<double>& A, LineGluingReport* report) {
  return line_gluing(t, [&](int v, int) { return A[v]; }, report);
}

std::vector<SplitGluing> line_gluing(const QuadTopology& t, const EndValue& A, LineGluingReport* report) {
  std::vector<char> used(t.num_edges(), 0);
  for (int e = 0; e < t.num_edges(); ++e) used[e] = t.edge(e).boundary() ? 1 : 0;
  std::vector<GluingLine> lines;
  for (int e = 0; e < t.num_edges(); ++e)
    if (!used[e]) lines.push_back(trace_line(t, e, used));

  // Linear along each open line (in the edge count); closed lines carry a ≡ 0.
  for (GluingLine& l : lines) {
    const int L = static_cast<int>(l.e.size());
    l.value.assign(L + 1, 0.0);
    if (!l.closed) {
      const double first = A(l.v.front(), l.e.front()), last = -A(l.v.back(), l.e.back());
      for (int j = 0; j <= L; ++j) l.value[j] = first + (last - first) * j / L;
    }
    for (double& x : l.value)
      if (std::abs(x) < kZero) x = 0.0;
  }
  // Conflicts: two non-zero passes at one interior valence-4 vertex.
  std::vector<std::vector<std::pair<int, int>>> passes(t.num_vertices());  // (line, position)
  for (std::size_t i = 0; i < lines.size(); ++i)
    if (!lines[i].closed)  // a closed line is zero everywhere
      for (std::size_t j = 1; j + 1 < lines[i].v.size(); ++j)
        passes[lines[i].v[j]].emplace_back(static_cast<int>(i), static_cast<int>(j));
  std::vector<char> zigzag(lines.size(), 0);
  for (;;) {
    std::vector<int> conflicts(lines.size(), 0);
    bool any = false;
    for (int v = 0; v < t.num_vertices(); ++v) {
      std::vector<int> nonzero;
      for (const auto& [i, j] : passes[v])
        if (!zigzag[i] && lines[i].value[j] != 0.0) nonzero.push_back(i);
      if (nonzero.size() < 2) continue;
      any = true;
      for (int i : nonzero) ++conflicts[i];
    }
    if (!any) break;
    // The line in most conflicts becomes a zigzag line (ties: the first).
    const int worst = static_cast<int>(std::max_element(conflicts.begin(), conflicts.end()) - conflicts.begin());
    zigzag[worst] = 1;
  }
  // Zigzag lines: 0 inside, mid-edge values ±μ alternating, μ from the ends' linear halves.
  for (std::size_t i = 0; i < lines.size(); ++i) {
    GluingLine& l = lines[i];
    const int L = static_cast<int>(l.e.size());
    l.mid.assign(L, 0.0);
    if (!zigzag[i]) {
      for (int j = 0; j < L; ++j) l.mid[j] = 0.5 * (l.value[j] + l.value[j + 1]);
      continue;
    }
    const double from_first = 0.5 * l.value.front();
    const double from_last = 0.5 * l.value.back() * ((L - 1) % 2 ? -1.0 : 1.0);
    double mu = std::abs(from_first) >= std::abs(from_last) ? from_first : from_last;
    if (from_first * from_last > 0) mu = 0.5 * (from_first + from_last);
    for (int j = 1; j < L; ++j) l.value[j] = 0.0;
    for (int j = 0; j < L; ++j) l.mid[j] = (j % 2 ? -mu : mu);
  }
  std::vector<SplitGluing> g(t.num_edges());
  for (const GluingLine& l : lines)
    for (std::size_t j = 0; j < l.e.size(); ++j) {
      const int e = l.e[j];
      const double a0 = l.value[j], m = l.mid[j], a1 = l.value[j + 1];
      const bool forward = t.edge(e).g0 == l.v[j];
      g[e] = forward ? SplitGluing::piecewise_linear(a0, m, a1) : SplitGluing::piecewise_linear(-a1, -m, -a0);
    }
  if (report) {
    report->lines = static_cast<int>(lines.size());
    report->zigzag_lines = static_cast<int>(std::count(zigzag.begin(), zigzag.end(), 1));
  }
  return g;
}

std::vector<SplitGluing> vertexwise_gluing(const QuadTopology& t, const EndValue& A, LineGluingReport* report) {
  // True crossings: interior vertices whose edges all have value 0.
  std::vector<char> crossing(t.num_vertices(), 0);
  for (int v = 0; v < t.num_vertices(); ++v) {
    if (t.vertex_on_boundary(v) || t.vertex_edges(v).size() != 4) continue;
    bool all = true;
    for (int e : t.vertex_edges(v)) all = all && std::abs(A(v, e)) < kZero;
    crossing[v] = all;
  }
  std::vector<double> a0(t.num_edges(), 0.0), a1(t.num_edges(), 0.0), mid(t.num_edges(), 0.0);
  for (int e = 0; e < t.num_edges(); ++e) {
    if (t.edge(e).boundary()) continue;
    a0[e] = crossing[t.edge(e).g0] ? 0.0 : A(t.edge(e).g0, e);
    a1[e] = crossing[t.edge(e).g1] ? 0.0 : -A(t.edge(e).g1, e);
    mid[e] = 0.5 * (a0[e] + a1[e]);
  }
  // Chains through true crossings (forward orientation along the chain).
  std::vector<char> done(t.num_edges(), 0);
  int chains = 0;
  for (int start = 0; start < t.num_edges(); ++start) {
    if (done[start] || t.edge(start).boundary()) continue;
    const int g0 = t.edge(start).g0, g1 = t.edge(start).g1;
    if (!crossing[g0] && !crossing[g1]) continue;  // no constraint on this edge's mid value
    // Walk back to the chain's first edge, then forward; (edge, forward?) in chain order.
    int e = start, from = g1;  // walking backwards: leave through g0
    for (int guard = 0; guard < t.num_edges(); ++guard) {
      const int v = t.edge(e).g0 == from ? t.edge(e).g1 : t.edge(e).g0;
      if (!crossing[v]) break;
      const int prev = opposite_edge(t, v, e);
      if (prev == start) break;  // closed chain: any start
      from = v;
      e = prev;
    }
    // Now `e` is the first edge, entered from its end opposite to `from`... orient: it starts at
    // the vertex that is not `from`'s side of the walk.
    int v = t.edge(e).g0 == from ? t.edge(e).g1 : t.edge(e).g0;  // the chain's first vertex
    std::vector<std::pair<int, bool>> chain;
    bool closed = false;
    for (int guard = 0; guard <= t.num_edges(); ++guard) {
      chain.emplace_back(e, t.edge(e).g0 == v);
      done[e] = 1;
      v = t.edge(e).g0 == v ? t.edge(e).g1 : t.edge(e).g0;
      if (!crossing[v]) break;
      e = opposite_edge(t, v, e);
      if (e == chain.front().first) {
        closed = true;
        break;
      }
    }
    ++chains;
    // Forward mids of the linear data, with the chain's alternating sign.
    double sum = 0.0, big = 0.0;
    int big_j = 0;
    std::vector<double> m(chain.size());
    for (std::size_t j = 0; j < chain.size(); ++j) {
      const auto [edge, forward] = chain[j];
      m[j] = (forward ? 1.0 : -1.0) * mid[edge] * (j % 2 ? -1.0 : 1.0);
      sum += m[j];
      if (std::abs(m[j]) > big) big = std::abs(m[j]), big_j = static_cast<int>(j);
    }
    if (closed && chain.size() % 2 == 1 && big > kZero) return {};  // μ = −μ with a kink
    double mu = closed && chain.size() % 2 == 1 ? 0.0 : sum / static_cast<double>(chain.size());
    if (big > kZero && std::abs(mu) < 0.5 * big) mu = m[big_j];  // keep a(½) away from 0 at kinks
    for (std::size_t j = 0; j < chain.size(); ++j) {
      const auto [edge, forward] = chain[j];
      mid[edge] = (forward ? 1.0 : -1.0) * mu * (j % 2 ? -1.0 : 1.0);
    }
  }
  std::vector<SplitGluing> g(t.num_edges());
  for (int e = 0; e < t.num_edges(); ++e) {
    if (t.edge(e).boundary()) continue;
    // A kink at ½ with a(½) = 0 would force p'(½) = 0 on every function (singular geometry).
    const double kink = (a1[e] - mid[e]) - (mid[e] - a0[e]);
    if (std::abs(mid[e]) < kZero && std::abs(kink) > kZero) return {};
    g[e] = SplitGluing::piecewise_linear(a0[e], mid[e], a1[e]);
  }
  if (twist_incompatible_vertex(t, g) >= 0) return {};
  if (report) {
    report->lines = chains;
    report->zigzag_lines = 0;
    report->mesh_fans = true;
  }
  return g;
}

int twist_incompatible_vertex(const QuadTopology& t, const std::vector<SplitGluing>& gluing) {
  for (int v = 0; v < t.num_vertices(); ++v) {
    if (t.vertex_on_boundary(v)) continue;
    bool crossing = true;
    double scale = 1.0;
    for (int e : t.vertex_edges(v)) {
      const bool start = t.edge(e).g0 == v;
      crossing = crossing && std::abs(gluing[e].eval(start ? 0.0 : 1.0, 0, start ? 0 : 1)) < kZero;
      scale = std::max(scale, std::abs(gluing[e].eval(start ? 0.0 : 1.0, 1, start ? 0 : 1)));
    }
    if (!crossing) continue;
    // The outward slope d/ds of a seen from v is a'(0) at g0 and a'(1) at g1 (a -> -a(1 - s)).
    auto slope = [&](int e) {
      const bool start = t.edge(e).g0 == v;
      return gluing[e].eval(start ? 0.0 : 1.0, 1, start ? 0 : 1);
    };
    for (int e : t.vertex_edges(v)) {
      const int o = opposite_edge(t, v, e);
      if (o < 0) {
        if (std::abs(slope(e)) > 1e-9 * scale) return v;  // not valence 4: no pairs, slopes must vanish
      } else if (std::abs(slope(e) - slope(o)) > 1e-9 * scale) {
        return v;
      }
    }
  }
  return -1;
}

}  // namespace iga
