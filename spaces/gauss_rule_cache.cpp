#include "spaces/gauss_rule_cache.hpp"

#include <algorithm>

#include "spaces/space.hpp"

namespace iga {

namespace {

/// The rule stored under `key`, made by `make` on first use (caller holds the lock).
template <class Map, class Key, class Make>
RulePtr cached(Map& rules, const Key& key, Make&& make) {
  RulePtr& r = rules[key];
  if (!r) r = std::make_shared<const QuadratureRule>(make());
  return r;
}

/// Gauss rule exact for `degree` on each of `pieces` equal parts of [0,1] (x coordinate).
QuadratureRule gauss_on_parts(int degree, int pieces) {
  const QuadratureRule g = gauss_legendre_for_degree(degree);
  if (pieces == 1) return g;
  QuadratureRule line;
  line.degree = g.degree;
  for (int piece = 0; piece < pieces; ++piece)
    for (int k = 0; k < g.size(); ++k) {
      line.points.emplace_back((piece + g.points[k].x()) / pieces, 0.0);
      line.weights.push_back(g.weights[k] / pieces);
    }
  return line;
}

}  // namespace

RulePtr GaussRuleCache::cell(int degree) const {
  degree = std::max(degree, 0);
  std::lock_guard<std::mutex> lock(mutex_);
  return cached(cells_, degree, [&] {
    const QuadratureRule ref = tensor_gauss(degree);
    if (pieces_ == 1) return ref;
    std::vector<QuadratureRule> parts;
    for (int j = 0; j < pieces_; ++j)
      for (int i = 0; i < pieces_; ++i)
        parts.push_back(map_to_box(ref, Point2(i, j) / pieces_, Point2(i + 1, j + 1) / pieces_));
    return concatenate(parts);
  });
}

RulePtr GaussRuleCache::edge(int edge, int degree) const {
  degree = std::max(degree, 0);
  std::lock_guard<std::mutex> lock(mutex_);
  return cached(edges_, std::make_pair(edge, degree),
                [&] { return edge_rule(CellShape::quadrilateral, edge, gauss_on_parts(degree, pieces_)); });
}

RulePtr GaussRuleCache::triangle(int degree) const {
  degree = std::max(degree, 0);
  std::lock_guard<std::mutex> lock(mutex_);
  return cached(triangles_, degree, [&] { return triangle_rule(degree); });
}

RulePtr GaussRuleCache::triangle_edge(int edge, int degree) const {
  degree = std::max(degree, 0);
  std::lock_guard<std::mutex> lock(mutex_);
  return cached(triangle_edges_, std::make_pair(edge, degree),
                [&] { return edge_rule(CellShape::triangle, edge, gauss_on_parts(degree, pieces_)); });
}

RulePtr GaussRuleCache::made(int degree, const std::function<QuadratureRule()>& make) const {
  degree = std::max(degree, 0);
  std::lock_guard<std::mutex> lock(mutex_);
  return cached(made_, degree, make);
}

}  // namespace iga
