#pragma once
/// @file
/// The tables of an eigen study (problem.eigen): eigenvalues.csv, whose header starts exactly with
/// level,h,dofs,index,eigenvalue,reference,relative_error,rate,rate_dofs (the last four empty
/// where there is no reference or no previous level), and the same as aligned text.

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "output/eigen_plot.hpp"
#include "solver/eigen_spec.hpp"
#include "solver/eigen_table.hpp"

namespace iga {

void write_eigenvalues_csv(const std::vector<EigenRow>& rows, const std::string& filename);

/// One line per eigenvalue and level, grouped by index so that a reader follows one eigenvalue
/// down the levels with its error and rate.
std::string format_eigen_table(const std::vector<EigenRow>& rows);

/// spectrum.csv (`level,n,N,eigenvalue,reference,ratio`) of the levels with a whole spectrum
/// (eigen.spectrum), references from the formula of `exact_eigenvalues` (or its list, as far as it
/// goes), and with `plot` spectrum.svg: λ_h,n / λ_n over n / N, one curve per level with references
/// for its whole spectrum. Nothing when no level has one.
void write_spectrum_files(const EigenSpec& spec, const std::vector<EigenLevel>& levels, const std::string& directory,
                          const std::string& title, bool plot);

/// The normalized spectrum λ_h,n / λ_n of the finest level with a whole spectrum and references for
/// all of it, labelled `label` and its N (for a comparison of spaces: one curve per space); none
/// when no level has both.
std::optional<SpectrumCurve> finest_normalized_spectrum(const EigenSpec& spec, const std::vector<EigenLevel>& levels,
                                                        const std::string& label);

/// A comparison of spaces: per space and level, the DOFs and the largest relative eigenvalue error.
std::string format_eigen_comparison(const std::vector<std::pair<std::string, std::vector<EigenRow>>>& spaces);

/// The rows for summary.json.
nlohmann::json eigen_json(const std::vector<EigenRow>& rows);

}  // namespace iga
