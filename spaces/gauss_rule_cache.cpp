#include "spaces/gauss_rule_cache.hpp"

#include <algorithm>

#include "spaces/space.hpp"

namespace iga {

RulePtr GaussRuleCache::cell(int degree) const {
  degree = std::max(degree, 0);
  std::lock_guard<std::mutex> lock(mutex_);
  RulePtr& r = cells_[degree];
  if (!r) r = std::make_shared<const QuadratureRule>(tensor_gauss(degree));
  return r;
}

RulePtr GaussRuleCache::edge(int edge, int degree) const {
  degree = std::max(degree, 0);
  std::lock_guard<std::mutex> lock(mutex_);
  RulePtr& r = edges_[{edge, degree}];
  if (!r)
    r = std::make_shared<const QuadratureRule>(
        edge_rule(CellShape::quadrilateral, edge, gauss_legendre_for_degree(degree)));
  return r;
}

RulePtr GaussRuleCache::triangle(int degree) const {
  degree = std::max(degree, 0);
  std::lock_guard<std::mutex> lock(mutex_);
  RulePtr& r = triangles_[degree];
  if (!r) r = std::make_shared<const QuadratureRule>(triangle_rule(degree));
  return r;
}

RulePtr GaussRuleCache::triangle_edge(int edge, int degree) const {
  degree = std::max(degree, 0);
  std::lock_guard<std::mutex> lock(mutex_);
  RulePtr& r = triangle_edges_[{edge, degree}];
  if (!r)
    r = std::make_shared<const QuadratureRule>(edge_rule(CellShape::triangle, edge, gauss_legendre_for_degree(degree)));
  return r;
}

}  // namespace iga
