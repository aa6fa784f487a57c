#pragma once
/// @file
/// Evaluation of functions on one face of the 4-split space: tensor-product B-spline tables at
/// reference points, the jet of a coefficient vector (value and derivatives up to order 2), and the
/// Bernstein coefficients of a polynomial piece (one of the 4 sub-squares).

#include <Eigen/Core>
#include <vector>

#include "quadrature/quadrature_rule.hpp"
#include "spaces/g1_4split/split_bspline.hpp"

namespace iga {

/// Tables of all (m+1)² tensor functions at the points, (m+1)² x q each: value, d/du, d/dv,
/// d²/du², d²/dudv, d²/dv². A coordinate exactly 1/2 is evaluated on the right piece.
void tensor_tables(const SplitBSpline& b, const std::vector<Point2>& points, Eigen::MatrixXd (&tables)[6]);

/// Value and derivatives of Σ c_l N_l at uv: (value, du, dv, duu, duv, dvv).
Eigen::Matrix<double, 6, 1> face_jet(const SplitBSpline& b, const Eigen::VectorXd& coefficients, const Point2& uv);

/// Bernstein coefficients ((k+1) x (k+1), entry (i, j) with i along u) of the piece of Σ c_l N_l on
/// the sub-square [hu/2, (hu+1)/2] x [hv/2, (hv+1)/2].
Eigen::MatrixXd piece_bernstein(const SplitBSpline& b, const Eigen::VectorXd& coefficients, int hu, int hv);

/// B-spline coefficients of a face function given by values f(u, v), by interpolation at the
/// Greville points (exact when f lies in the face space).
Eigen::VectorXd interpolate_face(const SplitBSpline& b, const std::vector<double>& values_at_greville);

}  // namespace iga
