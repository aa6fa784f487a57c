#pragma once
/// @file
/// The rules a space of plain (non-split) quadrilaterals and triangles hands out, built once and
/// shared: one cell rule per degree and one edge rule per (edge, degree) for each reference cell.
/// Sharing matters beyond saving work: evaluators cache reference tables by rule address.
/// Thread-safe.

#include <map>
#include <mutex>
#include <utility>

#include "quadrature/quadrature_rule.hpp"

namespace iga {

class GaussRuleCache {
 public:
  /// Tensor Gauss rule on [0,1]^2 exact for `degree` per direction.
  RulePtr cell(int degree) const;
  /// Gauss rule on edge `edge` of the reference square (space.hpp numbering), exact for `degree`.
  RulePtr edge(int edge, int degree) const;
  /// triangle_rule(degree) on the unit triangle (exact for total degree `degree`).
  RulePtr triangle(int degree) const;
  /// Gauss rule on edge `edge` of the reference triangle (space.hpp numbering), exact for `degree`.
  RulePtr triangle_edge(int edge, int degree) const;

 private:
  mutable std::mutex mutex_;
  mutable std::map<int, RulePtr> cells_;
  mutable std::map<std::pair<int, int>, RulePtr> edges_;
  mutable std::map<int, RulePtr> triangles_;
  mutable std::map<std::pair<int, int>, RulePtr> triangle_edges_;
};

}  // namespace iga
