#pragma once
/// @file
/// A fair isoparametric map for planar 4-split meshes. Where the bilinear mesh map is not in the
/// space, the least-squares fit (project_geometry) rounds every kink of the isolines within a
/// sub-square, oscillating at the scale of its knot spacing: derivatives of order j of the map grow
/// like kink · (2k / h₀)^j and u ∘ G with them. Here the map G minimises, among the maps of the
/// space whose boundary edges lie on the mesh's boundary segments (boundary vertices fixed, the
/// straight edges straight),
///     Σ_faces ∫ |D^n (G − B)|² + w |G − B|²      (face parameters, B the bilinear map),
/// so the correction G − B is spread over the face as smoothly as the space allows. Where B is in
/// the space (regular and once-split fans) the minimum is B itself: those maps do not move.

#include <string>

#include "spaces/g1/patch_mesh.hpp"
#include "spaces/g1_4split/g1_4split_basis.hpp"
#include "spaces/g1_4split/g1_4split_geometry.hpp"

namespace iga {

/// The energy: order n of the derivatives and weight w of the fit to the mesh. n = 3 measured best
/// on the Gmsh pentagon (H2 at level 1: 7.7e-3 for n = 2, 9.6e-4 for n = 3, where the least-squares
/// fit has 4.4e-2; n = 4 loses det J > 0, n = 5 gives 5.6e-3); w from 1e-4 to 1e-2 changes nothing in
/// 3 digits there (the conditions and the gluing fix the low modes), it only keeps the energy
/// definite. On finer Gmsh meshes with the mesh-fan gluing n = 3 folds and G14Space falls back to
/// n = 2 (thin plate); with the symmetric gluing, which the default takes there, n = 3 is certified.
struct FairFit {
  int order = 3;
  double fit_weight = 1e-2;
};

/// The fair map of `mesh` (the level mesh of `topology`, same vertex ids) in the space of `basis`.
/// Throws NumericalError if the boundary constraints cannot be met by the space (their residual is
/// checked after the solve).
FaceGeometry fair_geometry(const G14Basis& basis, const QuadTopology& topology, const PatchMesh& mesh,
                           const FairFit& fit = {});

/// Gram matrix of the n-th derivatives of the univariate basis on [0, 1] (exact Gauss rule per half).
Eigen::MatrixXd derivative_gram_1d(const SplitBSpline& b, int n);

}  // namespace iga
