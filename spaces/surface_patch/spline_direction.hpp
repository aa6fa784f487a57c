#pragma once
/// @file
/// One parameter direction of a surface_patch space: the univariate splines of degree p on [0, 1]
/// with given breakpoints and a continuity at each, either *open* (clamped ends: an open knot
/// vector) or *periodic* (the splines of the circle [0, 1) with 0 ≡ 1, the seam a breakpoint like
/// any other). Per element (span between breakpoints): its parameter interval, its p + 1 active
/// global functions and the Bézier extraction (active × Bernstein).
///
/// Periodic splines: the knots of one period τ_0 ≤ … ≤ τ_{N−1} (breakpoint k repeated p − c_k
/// times, the seam at 0 included) extended by t_{i+rN} = τ_i + r; the B-spline on t_j … t_{j+p+1}
/// is global function j mod N. There are N of them, and N ≥ p + 1 is needed so that no span sees one
/// function twice.

#include <Eigen/Core>
#include <vector>

#include "spaces/bspline/knot_vector.hpp"

namespace iga {

struct SplineDirection {
  int degree = 0;
  bool periodic = false;
  int num_functions = 0;
  std::vector<double> element_lo, element_hi;    ///< parameter interval of each element
  std::vector<std::vector<int>> active;          ///< p + 1 global functions per element
  std::vector<Eigen::MatrixXd> extraction;       ///< (p+1) × (p+1), active × Bernstein, per element
  /// Open directions: the knot vector (the planar space of the clamped boundary conditions uses it).
  std::vector<double> open_knots;
  /// Smallest continuity over the breakpoints (interior ones, and the seam when periodic).
  int min_continuity = 0;

  int num_elements() const { return static_cast<int>(element_lo.size()); }
};

/// `breakpoints` b_0 = 0 < … < b_M = 1; `continuity[k]` ∈ [−1, p − 1] at b_k for k = 0 … M − 1
/// (continuity[0] is the seam's, used only when periodic; open directions read k = 1 … M − 1).
/// Throws std::invalid_argument on a periodic direction with fewer than p + 1 functions per period.
SplineDirection make_spline_direction(int degree, bool periodic, const std::vector<double>& breakpoints,
                                      const std::vector<int>& continuity);

}  // namespace iga
