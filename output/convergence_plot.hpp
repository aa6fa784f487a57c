#pragma once
/// @file
/// Log-log convergence plot (errors against h and against DOFs, with reference slopes) drawn with
/// PLplot's SVG driver.

#include <string>
#include <vector>

#include "solver/level_result.hpp"

namespace iga {

/// Draw L2, H1 and H2 errors of `rows` against h (left panel) and DOFs (right panel), with dashed
/// reference slopes h^{expected.l2}, h^{expected.h1}, h^{expected.h2}. Does nothing when no row
/// has an error. Throws std::runtime_error if the file cannot be written.
void plot_convergence(const std::vector<LevelResult>& rows, const OptimalRates& expected, const std::string& title,
                      const std::string& filename);

}  // namespace iga
