#pragma once
/// @file
/// The rules a space hands out, built once and shared: one cell rule per degree and one edge rule
/// per (edge, degree) for each reference cell. Sharing matters beyond saving work: evaluators
/// cache reference tables by rule address. A space whose polynomial pieces split each cell (the
/// 4-split's sub-squares) or each edge (WS4's quarters) asks for rules composite over `pieces`
/// equal parts per direction. Thread-safe.

#include <functional>
#include <map>
#include <mutex>
#include <tuple>

#include "quadrature/quadrature_rule.hpp"

namespace iga {

class GaussRuleCache {
 public:
  explicit GaussRuleCache(int pieces = 1) : pieces_(pieces) {}

  /// Tensor Gauss rule on each of the pieces² equal sub-squares of [0,1]^2, exact for `degree` per direction.
  RulePtr cell(int degree) const;
  /// Gauss rule on each of the `pieces` parts of edge `edge` of the reference square (space.hpp numbering).
  RulePtr edge(int edge, int degree) const;
  /// triangle_rule(degree) on the unit triangle (exact for total degree `degree`).
  RulePtr triangle(int degree) const;
  /// Gauss rule on each of the `pieces` parts of edge `edge` of the reference triangle (space.hpp numbering).
  RulePtr triangle_edge(int edge, int degree) const;
  /// A cell rule of the space's own making for `degree` (WS4's composite rule over its split).
  RulePtr made(int degree, const std::function<QuadratureRule()>& make) const;

 private:
  enum Kind { kCell, kEdge, kTriangle, kTriangleEdge, kMade };
  /// The rule of (kind, edge, max(degree, 0)), made by `make` (given that degree) on first use.
  RulePtr get(Kind kind, int edge, int degree, const std::function<QuadratureRule(int)>& make) const;

  int pieces_;
  mutable std::mutex mutex_;
  mutable std::map<std::tuple<int, int, int>, RulePtr> rules_;
};

}  // namespace iga
