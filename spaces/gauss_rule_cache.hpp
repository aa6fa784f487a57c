#pragma once
/// @file
/// The Gauss rules a quadrilateral-element space hands out, built once and shared: one tensor rule
/// per degree and one edge rule per (edge, degree). Sharing matters beyond saving work: evaluators
/// cache reference tables by rule address. Thread-safe.

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

 private:
  mutable std::mutex mutex_;
  mutable std::map<int, RulePtr> cells_;
  mutable std::map<std::pair<int, int>, RulePtr> edges_;
};

}  // namespace iga
