#pragma once
/// @file
/// The difference between the discrete solutions of two levels, u_fine − u_coarse, in L2 and the H1
/// and H2 seminorms, integrated over the fine mesh with its error rule: exact (up to quadrature)
/// for nested spaces, where u_coarse is piecewise polynomial on the fine elements too. Without an
/// exact solution, these differences between successive levels show the convergence.

#include <Eigen/Core>
#include <functional>

#include "assembly/error_norms.hpp"
#include "spaces/point_location.hpp"

namespace iga {

/// ‖u_f − u_c‖_L2, |u_f − u_c|_H1 and (with `hessians`) |u_f − u_c|_H2 on the fine space's elements,
/// with the rule of each fine element given by `rule_of(element)`. u_c is evaluated at the fine quadrature points located in the
/// coarse space: each fine element's centre is located once, and its points are mapped into that
/// coarse element together (a fine element of a nested refinement lies in one coarse element);
/// points outside it are located one by one. Planar spaces only.
ErrorNorms level_difference(const Space& fine, const Eigen::VectorXd& fine_coefficients, const PointLocator& coarse,
                            const Eigen::VectorXd& coarse_coefficients, bool hessians,
                            const std::function<RulePtr(int)>& rule_of);

/// The rule a study uses for the differences on `fine`: degree 2p on affine elements (exact for
/// nested spaces: (u_l − u_{l−1})² is a polynomial of degree 2p on each fine piece), the error rule
/// on curved ones. A macro-element whose composite rule has far more points than a plain rule
/// (WS4: 342 pieces) gets a plain rule of that degree on 16 equal sub-cells instead: its pieces
/// join C^k (k ≥ 1) and the coarse split does not follow the fine one anyway, so the composite
/// rule buys no exactness, only cost.
std::function<RulePtr(int)> difference_rule(const Space& fine);

}  // namespace iga
