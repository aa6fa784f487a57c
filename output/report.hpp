#pragma once
/// @file
/// The study's tables: convergence.csv (a contract: its header starts exactly with
/// level,h,dofs,l2,h1,h2,rate_l2,rate_h1,rate_h2,t_assemble,t_solve), the aligned stdout table and
/// summary.json.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "solver/study.hpp"

namespace iga {

/// Levels at the round-off floor of each norm (solver/level_result.hpp: round_off_floor), measured
/// against h, or against N^(-1/2) in adaptive studies.
struct RoundOffFloor {
  std::vector<bool> l2, h1, h2;
  bool any() const;
};
RoundOffFloor round_off_levels(const std::vector<LevelResult>& rows, bool adaptive);

/// True when some level has an error against an exact solution.
bool has_errors(const std::vector<LevelResult>& rows);

/// Columns floor_l2, floor_h1, floor_h2 (1 at the round-off floor) follow the documented ones.
/// Then energy, energy_difference, rate_energy_difference and, per functional name, its value and
/// Richardson order (columns <name>, order_<name>).
void write_convergence_csv(const std::vector<LevelResult>& rows, const std::string& filename, bool adaptive = false,
                           const std::vector<std::string>& functional_names = {});

/// The convergence table as aligned text, one row per level, rates from consecutive levels.
/// With `rates_against_dofs` (adaptive studies) the rate columns are log(e_prev/e)/log(N/N_prev).
/// Rates of levels at the round-off floor carry a '*', explained below the table.
/// Without errors (no exact solution) the columns are the energy, the energy-norm difference to
/// the previous level with its rate, and each functional with its Richardson order.
std::string format_convergence_table(const std::vector<LevelResult>& rows, bool rates_against_dofs = false,
                                     const std::vector<std::string>& functional_names = {});

/// The names of the study's functionals.
std::vector<std::string> functional_names(const StudySettings& settings);

/// summary.json's text: config echo, space and parameters, rows, least-squares rates, timings.
std::string summary_json(const StudySettings& settings, const StudyResult& result);

/// Writes summary_json() to `filename`.
void write_summary_json(const StudySettings& settings, const StudyResult& result, const std::string& filename);

/// The config as JSON (the `config` echo of every summary.json).
nlohmann::json config_as_json(const ConfigNode& root);

}  // namespace iga
