#pragma once
/// @file
/// Log-log convergence plot (errors against h and against DOFs, with reference slopes) drawn with
/// PLplot's SVG driver.

#include <string>
#include <vector>

#include "solver/level_result.hpp"

namespace iga {

/// Draw the L2 error and the H1, H2 seminorm errors of `rows` against DOFs (left panel, with
/// dashed reference slopes DOF^(-expected/2) = h^expected starting at the data) and against the
/// time to solution (right panel); the y-range fits the data, levels at the round-off floor are
/// drawn as open circles. Does nothing when no row has an error. Throws std::runtime_error if the
/// file cannot be written.
void plot_convergence(const std::vector<LevelResult>& rows, const OptimalRates& expected, const std::string& title,
                      const std::string& filename, bool adaptive = false);

}  // namespace iga
