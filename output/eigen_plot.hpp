#pragma once
/// @file
/// The plots of an eigen study (PLplot SVG, like output/convergence_plot.hpp): the relative error
/// of each eigenvalue against DOFs, and the normalized spectrum λ_h,n / λ_n over n / N.

#include <string>
#include <vector>

#include "solver/eigen_table.hpp"

namespace iga {

/// Relative error against DOFs, one line per distinct reference eigenvalue (a multiple one is drawn
/// once), with a dashed slope DOF^(-rate/2) = h^rate. Does nothing without references.
void plot_eigen_errors(const std::vector<EigenRow>& rows, int expected_rate, const std::string& title,
                       const std::string& filename);

/// A comparison of spaces: per space (label, its rows), the largest relative error over the
/// eigenvalues with references against DOFs, one line per space.
void plot_eigen_comparison(const std::vector<std::pair<std::string, std::vector<EigenRow>>>& spaces,
                           const std::string& title, const std::string& filename);

/// The largest relative error of each level over the indices with a reference: (DOFs, error).
std::vector<std::pair<int, double>> worst_relative_errors(const std::vector<EigenRow>& rows);

/// λ_h,n / λ_n over n / N for each curve (label, ratios in order n = 1 .. N).
struct SpectrumCurve {
  std::string label;
  std::vector<double> ratios;
};
void plot_normalized_spectrum(const std::vector<SpectrumCurve>& curves, const std::string& title,
                              const std::string& filename);

}  // namespace iga
