#pragma once
/// @file
/// Bernstein polynomials of degree p on the reference triangle, λ = (1 − ξ − η, ξ, η), tabulated
/// at the points of a rule (values, first and second ξ, η derivatives; functions in bezier_index order).

#include <Eigen/Core>
#include <map>
#include <memory>

#include "quadrature/quadrature_rule.hpp"

namespace iga {

struct ReferenceBernstein {
  Eigen::MatrixXd value, dxi, deta;          ///< (p+1)(p+2)/2 x q
  Eigen::MatrixXd dxixi, dxieta, detaeta;    ///< (p+1)(p+2)/2 x q, empty unless asked for
};

/// The table of degree `degree` at the points of `points`, with second derivatives when `second`.
ReferenceBernstein reference_bernstein(int degree, const QuadratureRule& points, bool second = false);

/// Per-evaluator cache of tables keyed by rule address (rules are shared through RulePtr), checked
/// against the rule's size and first point in case an address is reused.
class ReferenceBernsteinCache {
 public:
  /// The table of `points`, with second derivatives when `second` (built again when a cached
  /// table lacks them).
  const ReferenceBernstein& get(int degree, const QuadratureRule& points, bool second = false);

 private:
  struct Entry {
    int size = 0;
    Point2 first;
    ReferenceBernstein table;
  };
  std::map<const QuadratureRule*, Entry> entries_;
};

}  // namespace iga
