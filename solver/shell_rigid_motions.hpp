#pragma once
/// @file
/// The rigid motions u = a + θ/L × (x − x₀) that a shell's supports leave free (docs/shells.md,
/// "Free shells"): their discrete representation, the coefficients pinned against them, the
/// load's equilibrium with them, and their removal after the solve.
///
/// Method. The free motions are the null space of "held component c of a + θ/L × (x − x₀) is zero
/// at sample points of every held edge" (an SVD of a 6-column matrix: x₀ the surface's centroid,
/// L its largest distance from x₀, so a and θ weigh alike). Each free motion's coefficients R are
/// the L2 projection of its three components (exact where 1, x, y, z are in the space: constants
/// always, the coordinates on isoparametric spaces such as the 4-split surfaces), with
/// F = M R = ∫ r·N_i. A column-pivoted QR of Rᵀ over the unheld coefficients picks one coefficient
/// per free motion such that those rows of R are independent: pinning them to zero removes the
/// kernel without constraining anything else when the motions are exact (the solution then
/// differs from any other by a kernel vector only). After the solve, the M-orthogonal projection
/// onto span R is subtracted: u ← u − R (FᵀR)⁻¹ Fᵀu, so the answer does not depend on the pins.
/// Where the coordinates are not in the space (polynomial B-splines on a rational patch), the
/// projected rotations have a small, nonzero energy: pinning then acts as a statically
/// determinate support whose reactions are the load's unbalance against the projected motions,
/// and vanish with refinement at the projection's rate.

#include <Eigen/Core>
#include <functional>
#include <string>
#include <vector>

#include "assembly/boundary_conditions.hpp"
#include "solver/shell_spec.hpp"
#include "spaces/space.hpp"

namespace iga {

/// The free rigid motions of a shell: columns (a, θ) of `modes` (6 × k, orthonormal), the motion
/// r(x) = a + θ/length × (x − center).
struct RigidMotions {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  double length = 1.0;
  Eigen::MatrixXd modes;  ///< 6 × k
  int count() const { return static_cast<int>(modes.cols()); }
  /// "translation along x, rotation about (0, 0, 1) through (…)" for messages.
  std::string describe() const;
};

/// The rigid motions that vanish in the held components on every held edge.
RigidMotions free_rigid_motions(const Space& space, const std::vector<ShellSupport>& supports, int quad_degree);

/// Resultant force and moment about `center` of the loads (per area and at points), and the total
/// magnitude ∫|f| + Σ|F_i| they are compared against. The force per area is f(element, x, n), n the
/// element's unit normal x_ξ × x_η / |x_ξ × x_η| (a pressure orients it per element).
struct LoadResultant {
  Eigen::Vector3d force = Eigen::Vector3d::Zero(), moment = Eigen::Vector3d::Zero();
  double magnitude = 0.0;
};
using AreaForce = std::function<Eigen::Vector3d(int element, const Eigen::Vector3d& x, const Eigen::Vector3d& n)>;
LoadResultant load_resultant(const Space& space, const AreaForce& f,
                             const std::vector<ShellPointLoad>& points, const Eigen::Vector3d& center, int quad_degree);

/// Discrete free rigid motions: coefficients R (3N × k, blocks by component) and F = M R.
struct RigidMotionBasis {
  Eigen::MatrixXd coefficients, moments;
};
RigidMotionBasis rigid_motion_basis(const Space& space, const RigidMotions& motions, int quad_degree);

/// Pin one unheld coefficient per free motion (column-pivoted QR of the rows of R left free by
/// `c`), moving them from c.free to c.constrained with value 0. Returns the pinned indices.
std::vector<int> pin_rigid_motions(const RigidMotionBasis& basis, Constraints& c);

/// u ← u − R (FᵀR)⁻¹ Fᵀu: the M-orthogonal projection onto the free rigid motions removed.
void remove_rigid_motions(const RigidMotionBasis& basis, Eigen::VectorXd& u);

}  // namespace iga
