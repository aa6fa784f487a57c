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

}  // namespace

RulePtr GaussRuleCache::cell(int degree) const {
  degree = std::max(degree, 0);
  std::lock_guard<std::mutex> lock(mutex_);
  return cached(cells_, degree, [&] { return tensor_gauss(degree); });
}

RulePtr GaussRuleCache::edge(int edge, int degree) const {
  degree = std::max(degree, 0);
  std::lock_guard<std::mutex> lock(mutex_);
  return cached(edges_, std::make_pair(edge, degree), [&] {
    return edge_rule(CellShape::quadrilateral, edge, gauss_legendre_for_degree(degree));
  });
}

RulePtr GaussRuleCache::triangle(int degree) const {
  degree = std::max(degree, 0);
  std::lock_guard<std::mutex> lock(mutex_);
  return cached(triangles_, degree, [&] { return triangle_rule(degree); });
}

RulePtr GaussRuleCache::triangle_edge(int edge, int degree) const {
  degree = std::max(degree, 0);
  std::lock_guard<std::mutex> lock(mutex_);
  return cached(triangle_edges_, std::make_pair(edge, degree), [&] {
    return edge_rule(CellShape::triangle, edge, gauss_legendre_for_degree(degree));
  });
}

}  // namespace iga
