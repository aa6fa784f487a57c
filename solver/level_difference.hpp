#pragma once
/// @file
/// The difference between the discrete solutions of two levels, u_fine − u_coarse, in L2 and the H1
/// and H2 seminorms, integrated over the fine mesh with its error rule: exact (up to quadrature)
/// for nested spaces, where u_coarse is piecewise polynomial on the fine elements too. Without an
/// exact solution, these differences between successive levels show the convergence.

#include <Eigen/Core>

#include "assembly/error_norms.hpp"
#include "spaces/point_location.hpp"

namespace iga {

/// ‖u_f − u_c‖_L2, |u_f − u_c|_H1 and (with `hessians`) |u_f − u_c|_H2 on the fine space's elements,
/// rules of degree `quad_degree`. u_c is evaluated at the fine quadrature points located in the
/// coarse space: each fine element's centre is located once, and its points are mapped into that
/// coarse element together (a fine element of a nested refinement lies in one coarse element);
/// points outside it are located one by one. Planar spaces only.
ErrorNorms level_difference(const Space& fine, const Eigen::VectorXd& fine_coefficients, const PointLocator& coarse,
                            const Eigen::VectorXd& coarse_coefficients, bool hessians, int quad_degree);

}  // namespace iga
