#pragma once
/// @file
/// Largest jump of the physical gradient of a piecewise polynomial across the interior edges of a
/// QuadMesh: the check that a discrete solution of a G1 space is C1 (the `g1_jump` column).

#include <Eigen/Core>
#include <vector>

#include "spaces/g1/quad_mesh.hpp"

namespace iga {

/// Number of samples per edge used by max_gradient_jump for degree k: the jump times both
/// Jacobian determinants is a polynomial of degree <= k+2 along a bilinear edge, so 2k+4 points
/// (endpoints included) cannot all miss a nonzero jump.
int gradient_jump_samples(int k);

/// max over interior edges and over gradient_jump_samples(k) equispaced points per edge of
/// |∇u_1 − ∇u_2| (Euclidean), where u_f is the polynomial of bidegree (k,k) on face f with tensor
/// Bernstein coefficients face_coefficients[f] (local index i + j*(k+1)), pushed to physical
/// coordinates through the face's bilinear map. 0 for a mesh without interior edges.
double max_gradient_jump(const QuadMesh& mesh, int k, const std::vector<Eigen::VectorXd>& face_coefficients);

}  // namespace iga
