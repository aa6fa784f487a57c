#pragma once
/// @file
/// The `g1_jump` check of convergence.csv, written once for every space: the largest jump of the
/// physical gradient (on surfaces in 3D: of the surface gradient) of a discrete function across
/// the interior edges of a space, from Space::interior_edges() and the space's own evaluator.

#include <Eigen/Core>

#include "spaces/space.hpp"

namespace iga {

/// max over the pieces of space.interior_edges() and over `samples` (>= 2) equispaced points of
/// each piece, endpoints included, of |∇u_a − ∇u_b| (Euclidean), u = Σ coefficients(i) N_i
/// evaluated on the elements of both sides. 0 for a space without interior edges.
double max_gradient_jump(const Space& space, const Eigen::VectorXd& coefficients, int samples);

}  // namespace iga
