#pragma once
/// @file
/// The isoparametric geometry of the 4-split G1 space: both coordinates of the map lie in the space
/// (notes §10.3), so φ ∘ G⁻¹ is C1 for every φ of the space. Built by a least-squares projection of
/// the mesh's bilinear parametrization, subdivided exactly for nested refinement, and certified
/// regular (det J > 0 on every closed face) from Bernstein coefficients of det J per polynomial piece.

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <string>
#include <vector>

#include "spaces/g1/patch_mesh.hpp"
#include "spaces/g1_4split/g1_4split_basis.hpp"

namespace iga {

/// Per face, the B-spline coefficients of x and y ((m+1)² each).
struct FaceGeometry {
  std::vector<Eigen::VectorXd> x, y;
};

/// The bilinear map of every face of `mesh` in the faces' B-spline bases (exact).
FaceGeometry bilinear_geometry(const PatchMesh& mesh, const SplitBSpline& b);

/// The face matrix of Gu ⊗ Gv on a face's coefficients (index i + j·size, i along u): 1D matrices
/// of the two directions combined (mass, derivative Grams).
Eigen::MatrixXd face_tensor_product(const Eigen::MatrixXd& Gu, const Eigen::MatrixXd& Gv);

/// The same face matrix on each of F faces: the operator on broken (per-face) coefficients.
Eigen::SparseMatrix<double> block_diagonal(const Eigen::MatrixXd& face_matrix, int faces);

/// The L2 (parameter-domain) projection of a broken geometry onto the space spanned by the basis.
FaceGeometry project_geometry(const G14Basis& basis, const FaceGeometry& broken);

/// The geometry of the refined mesh (children 4f + c as in QuadTopology::refined), the same map.
FaceGeometry subdivide_geometry(const SplitBSpline& b, const FaceGeometry& coarse);

/// One coordinate of child c (the quarter at corner c) of a face, from the face's coefficients:
/// what subdivide_geometry does for each face and child.
Eigen::VectorXd subdivided_face(const SplitBSpline& b, const Eigen::VectorXd& coarse, int child);

/// A lower bound of det J / (diameter² of the face's control net) on face f, certified from the
/// Bernstein coefficients of det J on each sub-square (recursively subdivided where needed);
/// <= 0 when positivity cannot be certified (in particular when det J <= 0 somewhere).
double certified_jacobian_bound(const SplitBSpline& b, const Eigen::VectorXd& x, const Eigen::VectorXd& y);

/// The largest ratio max det J / min det J inside one face (face parameters, a 25 × 25 grid of
/// samples per face), over the faces: how unevenly the map spreads each face's area. With b ≡ −1
/// det J is continuous across every edge, so faces of unequal area, and gluing that forces the map
/// away from the mesh's, show here (docs/spaces/g1_4split.md, "Which gluing values").
double largest_jacobian_ratio(const SplitBSpline& b, const FaceGeometry& g);

/// Throws InputError naming face f of `mesh_name` when the det J of its map (x, y) is not certified
/// positive (bound above 1e-8: a zero of det J leaves coefficients at round-off); `fair`: the map
/// is the fair one (the message names the other fit).
void check_face_geometry(const SplitBSpline& b, const Eigen::VectorXd& x, const Eigen::VectorXd& y, int f,
                         const std::string& mesh_name, bool fair);

}  // namespace iga
