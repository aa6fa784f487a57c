#pragma once
/// @file
/// One row of a convergence study: what was solved at one refinement level and how well.

#include <optional>
#include <string>
#include <vector>

namespace iga {

struct LevelResult {
  int level = 0;
  double h = 0;       ///< largest element diameter
  int dofs = 0;       ///< dimension of the space (before boundary conditions)
  int free_dofs = 0;  ///< unknowns after boundary conditions
  int elements = 0;   ///< elements of the space
  // Errors against the exact solution (absent without one): L2 norm, H1 and H2 *seminorms*.
  std::optional<double> l2, h1, h2;
  double t_space = 0, t_assemble = 0, t_solve = 0, t_errors = 0;  ///< seconds
  /// Largest gradient jump of the discrete solution across interior element edges
  /// (Space::max_gradient_jump; absent when the space does not compute it).
  std::optional<double> g1_jump;
  /// Energy a(u_h, u_h) of the discrete solution (planar problems).
  std::optional<double> energy;
  /// |u_l − u_{l−1}|_a = |a(u_l, u_l) − a(u_{l−1}, u_{l−1})|^½: the energy norm of the change from
  /// the previous level, exact for nested spaces with homogeneous essential data (Galerkin orthogonality).
  std::optional<double> energy_difference;
  /// ‖u_l − u_{l−1}‖_L2, |u_l − u_{l−1}|_H1, |u_l − u_{l−1}|_H2 (C1 spaces) on this level's mesh:
  /// the change from the previous level, computed in studies without an exact solution. For
  /// nested spaces it estimates the previous level's error.
  std::optional<double> difference_l2, difference_h1, difference_h2;
  /// Values of the study's functionals (output.functionals), in their order.
  std::vector<double> functionals;
  /// What the formulation said of this level (Formulation::notes: where each point load was placed).
  std::vector<std::string> notes;
};

/// Expected convergence orders of the L2 error and the H1, H2 seminorm errors.
struct OptimalRates {
  int l2 = 0, h1 = 0, h2 = 0;
};

/// Rate between two rows: log(e_prev / e) / log(h_prev / h); nullopt if either error is missing.
std::optional<double> rate(std::optional<double> e_prev, std::optional<double> e, double h_prev, double h);

/// Least-squares slope of log(e) against log(h) over all rows with an error (rows whose `skip`
/// entry is true are left out; `skip` may be empty).
std::optional<double> least_squares_rate(const std::vector<double>& h, const std::vector<std::optional<double>>& e,
                                         const std::vector<bool>& skip = {});

/// Levels at the round-off floor: from the first level whose error stops decreasing (its rate
/// below half the previous one and below 1) after a clean rate (>= 1) and far below the coarsest
/// error (1e-4 of it), to the last level. Such levels measure round-off, not discretization.
/// `x` is h (or 1/N for rates against DOFs); one flag per row.
std::vector<bool> round_off_floor(const std::vector<double>& x, const std::vector<std::optional<double>>& e);

}  // namespace iga
