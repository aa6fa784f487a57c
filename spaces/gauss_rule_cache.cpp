#include "spaces/gauss_rule_cache.hpp"

#include <algorithm>

#include "spaces/space.hpp"

namespace iga {

namespace {

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

RulePtr GaussRuleCache::get(Kind kind, int edge, int degree, const std::function<QuadratureRule(int)>& make) const {
  degree = std::max(degree, 0);
  std::lock_guard<std::mutex> lock(mutex_);
  RulePtr& r = rules_[{kind, edge, degree}];
  if (!r) r = std::make_shared<const QuadratureRule>(make(degree));
  return r;
}

RulePtr GaussRuleCache::cell(int degree) const {
  return get(kCell, 0, degree, [this](int d) {
    const QuadratureRule ref = tensor_gauss(d);
    if (pieces_ == 1) return ref;
    std::vector<QuadratureRule> parts;
    for (int j = 0; j < pieces_; ++j)
      for (int i = 0; i < pieces_; ++i)
        parts.push_back(map_to_box(ref, Point2(i, j) / pieces_, Point2(i + 1, j + 1) / pieces_));
    return concatenate(parts);
  });
}

RulePtr GaussRuleCache::edge(int edge, int degree) const {
  return get(kEdge, edge, degree,
             [&](int d) { return edge_rule(CellShape::quadrilateral, edge, gauss_on_parts(d, pieces_)); });
}

RulePtr GaussRuleCache::triangle(int degree) const {
  return get(kTriangle, 0, degree, [](int d) { return triangle_rule(d); });
}

RulePtr GaussRuleCache::triangle_edge(int edge, int degree) const {
  return get(kTriangleEdge, edge, degree,
             [&](int d) { return edge_rule(CellShape::triangle, edge, gauss_on_parts(d, pieces_)); });
}

RulePtr GaussRuleCache::made(int degree, const std::function<QuadratureRule()>& make) const {
  return get(kMade, 0, degree, [&](int) { return make(); });
}

}  // namespace iga
