#pragma once
/// @file
/// Largest jump of the physical gradient of a piecewise polynomial across the interior edges of a
/// PatchMesh: the check that a discrete solution of a G1 space is C1 (the `g1_jump` column).

#include <Eigen/Core>
#include <vector>

#include "spaces/g1/patch_mesh.hpp"

namespace iga {

/// Number of samples per edge used by max_gradient_jump for degree k: the jump times both
/// Jacobian determinants is a polynomial of degree <= k+2 along an edge, so 2k+4 points
/// (endpoints included) cannot all miss a nonzero jump.
int gradient_jump_samples(int k);

/// max over interior edges and over gradient_jump_samples(k) equispaced points per edge of
/// |∇u_1 − ∇u_2| (Euclidean), where u_f is the polynomial of degree k on face f (bidegree (k,k) on
/// a quad, total degree k on a triangle) with Bernstein coefficients face_coefficients[f] (local
/// indices of bernstein_face.hpp), pushed to physical coordinates through the face's map. 0 for a
/// mesh without interior edges.
double max_gradient_jump(const PatchMesh& mesh, int k, const std::vector<Eigen::VectorXd>& face_coefficients);

}  // namespace iga
