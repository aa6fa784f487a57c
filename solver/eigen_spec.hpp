#pragma once
/// @file
/// `problem.eigen`: the smallest eigenvalues of the problem's operator instead of a solve,
/// K x = λ M x on the functions that satisfy the homogeneous essential conditions (docs/eigen.md).

#include <string>
#include <vector>

#include "config/config_node.hpp"

namespace iga {

struct EigenSpec {
  int count = 1;  ///< how many of the smallest eigenvalues
  /// Reference eigenvalues in ascending order (with multiplicity), from `exact_eigenvalues`; may be
  /// shorter than `count` (the indices beyond have no reference).
  std::vector<double> exact;
  std::string where;  ///< config place of `eigen`, for messages found only while solving
  /// `exact_eigenvalues` as a formula in m, n (empty for a list): the references of a whole spectrum.
  std::string formula, formula_where;
  /// `spectrum: true`: every eigenvalue of the levels with at most max_spectrum_unknowns free
  /// unknowns (a dense solver), for spectrum.csv and the normalized spectrum.
  bool spectrum = false;
};

/// The dense solver of a whole spectrum costs O(n³) time and n² memory: 4000 unknowns take about
/// half a minute and 256 MB for each matrix.
constexpr int max_spectrum_unknowns = 4000;

/// Most eigenvalues one run may ask for: shift-and-invert Lanczos keeps 2·count vectors of the
/// size of the space.
constexpr int max_eigen_count = 500;

/// Parse `problem.eigen` (keys count, exact_eigenvalues, spectrum). `exact_eigenvalues` is a list of numbers
/// or constant expressions ("2*pi^2"), or one expression in m and n (a rectangle's λ_mn, increasing
/// in m and n) whose values over m, n = 1, 2, ... give the references in ascending order.
EigenSpec parse_eigen(const ConfigNode& node);

/// The `count` smallest values of f(m, n) over m, n >= 1, ascending and with multiplicity, for an
/// f increasing in m and in n. `where` names the formula in messages.
std::vector<double> eigenvalues_from_formula(const std::string& formula, const std::string& where, int count);

}  // namespace iga
