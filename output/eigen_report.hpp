#pragma once
/// @file
/// The tables of an eigen study (problem.eigen): eigenvalues.csv, whose header starts exactly with
/// level,h,dofs,index,eigenvalue,reference,relative_error,rate,rate_dofs (the last four empty
/// where there is no reference or no previous level), and the same as aligned text.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "solver/eigen_table.hpp"

namespace iga {

void write_eigenvalues_csv(const std::vector<EigenRow>& rows, const std::string& filename);

/// One line per eigenvalue and level, grouped by index so that a reader follows one eigenvalue
/// down the levels with its error and rate.
std::string format_eigen_table(const std::vector<EigenRow>& rows);

/// The rows for summary.json.
nlohmann::json eigen_json(const std::vector<EigenRow>& rows);

}  // namespace iga
