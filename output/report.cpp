#include "output/report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "output/eigen_report.hpp"
#include "output/surface_report.hpp"
#include "output/table_values.hpp"

namespace iga {

namespace {

struct Rates {
  std::optional<double> l2, h1, h2;
};

Rates rates_at(const std::vector<LevelResult>& rows, std::size_t i) {
  if (i == 0) return {};
  const LevelResult &a = rows[i - 1], &b = rows[i];
  return {rate(a.l2, b.l2, a.h, b.h), rate(a.h1, b.h1, a.h, b.h), rate(a.h2, b.h2, a.h, b.h)};
}

/// Rates against the number of DOFs N: e ~ N^(-rate), i.e. log(e_prev/e) / log(N/N_prev).
Rates dof_rates_at(const std::vector<LevelResult>& rows, std::size_t i) {
  if (i == 0) return {};
  const LevelResult &a = rows[i - 1], &b = rows[i];
  const double na = a.dofs, nb = b.dofs;
  return {rate(a.l2, b.l2, nb, na), rate(a.h1, b.h1, nb, na), rate(a.h2, b.h2, nb, na)};
}

std::ofstream open_for_writing(const std::string& filename) {
  std::ofstream out(filename);
  if (!out) throw std::runtime_error("cannot write " + filename);
  return out;
}

/// YAML scalars as JSON numbers or booleans when they read as such, strings otherwise.
nlohmann::json to_json(const YAML::Node& node) {
  switch (node.Type()) {
    case YAML::NodeType::Map: {
      nlohmann::json j = nlohmann::json::object();
      for (const auto& kv : node) j[kv.first.as<std::string>()] = to_json(kv.second);
      return j;
    }
    case YAML::NodeType::Sequence: {
      nlohmann::json j = nlohmann::json::array();
      for (const auto& item : node) j.push_back(to_json(item));
      return j;
    }
    case YAML::NodeType::Scalar: {
      if (node.Tag() == "!") return node.as<std::string>();  // quoted in the file: a string
      long long i;
      double d;
      bool b;
      if (YAML::convert<long long>::decode(node, i)) return i;
      if (YAML::convert<double>::decode(node, d)) return d;
      // Only true/false: yaml-cpp also reads y/n, yes/no and on/off as booleans (YAML 1.1), which
      // turned a shell's `fixed: [y, z]` into [true, "z"]; a key that takes a boolean reads those
      // itself (ConfigNode::as_bool), so echoing them as written is still a value it takes.
      const std::string& text = node.Scalar();
      static const std::set<std::string> kTrueFalse = {"true", "True", "TRUE", "false", "False", "FALSE"};
      if (kTrueFalse.count(text) && YAML::convert<bool>::decode(node, b)) return b;
      return node.as<std::string>();
    }
    default: return nullptr;
  }
}

/// problem.form as a config spells it (parse_problem accepts `laplacian` and `hessian`, biharmonic
/// only), so summary.json echoes a value a config can take; empty for Poisson, which has no form key.
std::string form_as_configured(const ProblemSpec& problem) {
  if (problem.pde != Pde::biharmonic) return {};
  return problem.terms.front()->name() == "hessian" ? "hessian" : "laplacian";
}

}  // namespace

bool RoundOffFloor::any() const {
  for (const auto* v : {&l2, &h1, &h2})
    if (std::find(v->begin(), v->end(), true) != v->end()) return true;
  return false;
}

RoundOffFloor round_off_levels(const std::vector<LevelResult>& rows, bool adaptive) {
  std::vector<double> x;
  std::vector<std::optional<double>> l2, h1, h2;
  for (const LevelResult& r : rows) {
    x.push_back(adaptive ? 1.0 / std::sqrt(std::max(1, r.dofs)) : r.h);
    l2.push_back(r.l2), h1.push_back(r.h1), h2.push_back(r.h2);
  }
  return {round_off_floor(x, l2), round_off_floor(x, h1), round_off_floor(x, h2)};
}

bool has_errors(const std::vector<LevelResult>& rows) {
  return std::any_of(rows.begin(), rows.end(), [](const LevelResult& r) { return r.l2 || r.h1 || r.h2; });
}

std::vector<std::string> functional_names(const StudySettings& settings) {
  std::vector<std::string> names;
  for (const FunctionalSpec& f : settings.functionals) names.push_back(f.name);
  return names;
}

namespace {

std::vector<double> mesh_sizes(const std::vector<LevelResult>& rows) {
  std::vector<double> h;
  for (const LevelResult& r : rows) h.push_back(r.h);
  return h;
}

/// Values of functional k over the rows.
std::vector<double> functional_values(const std::vector<LevelResult>& rows, std::size_t k) {
  std::vector<double> v;
  for (const LevelResult& r : rows) v.push_back(k < r.functionals.size() ? r.functionals[k] : NAN);
  return v;
}

/// Rates of the differences between successive levels (row i holds ‖u_i − u_{i−1}‖): against h,
/// or against N for adaptive runs.
Rates difference_rates_at(const std::vector<LevelResult>& rows, std::size_t i, bool against_dofs) {
  if (i == 0) return {};
  const LevelResult &a = rows[i - 1], &b = rows[i];
  const double xa = against_dofs ? static_cast<double>(b.dofs) : a.h, xb = against_dofs ? static_cast<double>(a.dofs) : b.h;
  return {rate(a.difference_l2, b.difference_l2, xa, xb), rate(a.difference_h1, b.difference_h1, xa, xb),
          rate(a.difference_h2, b.difference_h2, xa, xb)};
}

/// The table of a study without exact solution.
std::string format_difference_table(const std::vector<LevelResult>& rows, const std::vector<std::string>& names,
                                    bool rates_against_dofs) {
  std::ostringstream s;
  char line[512];
  const char* rate_label = rates_against_dofs ? "rate/N" : "rate";
  std::snprintf(line, sizeof line, "%5s %10s %8s %10s %6s %10s %6s %10s %6s %14s %11s %6s", "level", "h", "dofs",
                "L2(du)", rate_label, "H1(du)", rate_label, "H2(du)", rate_label, "energy", "|du|_a", rate_label);
  s << line;
  for (const std::string& n : names) {
    std::snprintf(line, sizeof line, " %16s %6s", n.substr(0, 16).c_str(), "order");
    s << line;
  }
  s << "   t_space  assemble     solve  t_errors\n";
  const std::vector<double> h = mesh_sizes(rows);
  const auto cell = [](std::optional<double> v, const char* format) { return v ? table_number(v, format) : std::string("-"); };
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const LevelResult& r = rows[i];
    const Rates d = difference_rates_at(rows, i, rates_against_dofs);
    const auto q = i == 0 ? std::nullopt
                   : rates_against_dofs
                       ? rate(rows[i - 1].energy_difference, r.energy_difference, r.dofs, rows[i - 1].dofs)
                       : rate(rows[i - 1].energy_difference, r.energy_difference, rows[i - 1].h, r.h);
    std::snprintf(line, sizeof line, "%5d %10.4e %8d %10s %6s %10s %6s %10s %6s %14s %11s %6s", r.level, r.h, r.dofs,
                  cell(r.difference_l2, "%.3e").c_str(), d.l2 ? table_number(d.l2, "%.2f").c_str() : "",
                  cell(r.difference_h1, "%.3e").c_str(), d.h1 ? table_number(d.h1, "%.2f").c_str() : "",
                  cell(r.difference_h2, "%.3e").c_str(), d.h2 ? table_number(d.h2, "%.2f").c_str() : "",
                  cell(r.energy, "%.8e").c_str(), cell(r.energy_difference, "%.3e").c_str(),
                  q ? table_number(q, "%.2f").c_str() : "");
    s << line;
    for (std::size_t k = 0; k < names.size(); ++k) {
      const std::vector<double> v = functional_values(rows, k);
      const auto order = richardson_order(v, h, i);
      std::snprintf(line, sizeof line, " %16.9e %6s", v[i], order ? table_number(order, "%.2f").c_str() : "");
      s << line;
    }
    std::snprintf(line, sizeof line, " %8.3fs %8.3fs %8.3fs %8.3fs\n", r.t_space, r.t_assemble, r.t_solve, r.t_errors);
    s << line;
  }
  s << "no exact solution: L2/H1/H2(du) = ||u_l - u_l-1|| on level l's mesh (L2 norm, H1 and H2 seminorms; for nested "
       "spaces an estimate of level l-1's error); |du|_a = |E_l - E_l-1|^1/2 (energy E = a(u_h,u_h); exact for nested "
       "spaces with homogeneous essential data); orders of functionals from three levels (Richardson)\n";
  return s.str();
}

}  // namespace

void write_convergence_csv(const std::vector<LevelResult>& rows, const std::string& filename, bool adaptive,
                           const std::vector<std::string>& functional_names) {
  std::ofstream out = open_for_writing(filename);
  const RoundOffFloor floor = round_off_levels(rows, adaptive);
  out << "level,h,dofs,l2,h1,h2,rate_l2,rate_h1,rate_h2,t_assemble,t_solve,free_dofs,t_space,t_errors,g1_jump,rate_dofs_l2,rate_dofs_h1,rate_dofs_h2,floor_l2,floor_h1,floor_h2,energy,energy_difference,rate_energy_difference,difference_l2,difference_h1,difference_h2,rate_difference_l2,rate_difference_h1,rate_difference_h2";
  for (const std::string& n : functional_names) out << ',' << n << ",order_" << n;
  out << '\n';
  const std::vector<double> h = mesh_sizes(rows);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const LevelResult& r = rows[i];
    const Rates q = rates_at(rows, i);
    out << r.level << ',' << table_number(r.h, "%.10e") << ',' << r.dofs << ',' << table_number(r.l2, "%.10e") << ','
        << table_number(r.h1, "%.10e") << ',' << table_number(r.h2, "%.10e") << ',' << table_number(q.l2, "%.4f") << ','
        << table_number(q.h1, "%.4f") << ',' << table_number(q.h2, "%.4f") << ',' << table_number(r.t_assemble, "%.6f") << ','
        << table_number(r.t_solve, "%.6f") << ',' << r.free_dofs << ',' << table_number(r.t_space, "%.6f") << ','
        << table_number(r.t_errors, "%.6f") << ',' << table_number(r.g1_jump, "%.3e");
    const Rates d = dof_rates_at(rows, i);
    out << ',' << table_number(d.l2, "%.4f") << ',' << table_number(d.h1, "%.4f") << ',' << table_number(d.h2, "%.4f") << ','
        << floor.l2[i] << ',' << floor.h1[i] << ',' << floor.h2[i] << ',' << table_number(r.energy, "%.15e") << ','
        << table_number(r.energy_difference, "%.10e") << ','
        << table_number(i > 0 ? rate(rows[i - 1].energy_difference, r.energy_difference, rows[i - 1].h, r.h) : std::nullopt,
                  "%.4f");
    const Rates dr = difference_rates_at(rows, i, adaptive);
    out << ',' << table_number(r.difference_l2, "%.10e") << ',' << table_number(r.difference_h1, "%.10e") << ','
        << table_number(r.difference_h2, "%.10e") << ',' << table_number(dr.l2, "%.4f") << ',' << table_number(dr.h1, "%.4f") << ','
        << table_number(dr.h2, "%.4f");
    for (std::size_t k = 0; k < functional_names.size(); ++k) {
      const std::vector<double> v = functional_values(rows, k);
      out << ',' << table_number(v[i], "%.15e") << ',' << table_number(richardson_order(v, h, i), "%.4f");
    }
    out << '\n';
  }
}

std::string format_convergence_table(const std::vector<LevelResult>& rows, bool rates_against_dofs,
                                     const std::vector<std::string>& functional_names) {
  if (!has_errors(rows) && !rows.empty()) return format_difference_table(rows, functional_names, rates_against_dofs);
  // The gradient-jump column appears only for spaces that compute it.
  const bool jumps = std::any_of(rows.begin(), rows.end(), [](const LevelResult& r) { return r.g1_jump.has_value(); });
  const RoundOffFloor floor = round_off_levels(rows, rates_against_dofs);
  std::ostringstream s;
  char line[256];
  // Against DOFs, "rate" is log(e_prev/e)/log(N/N_prev): h^k corresponds to N^(k/2) in 2D.
  const char* rate_label = rates_against_dofs ? "rate/N" : "rate";
  std::snprintf(line, sizeof line, "%5s %10s %8s %11s %6s %11s %6s %11s %6s %9s %9s %9s %9s", "level", "h", "dofs",
                "L2", rate_label, "H1-semi", rate_label, "H2-semi", rate_label, "t_space", "assemble", "solve",
                "t_errors");
  s << line << (jumps ? "   g1_jump\n" : "\n");
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const LevelResult& r = rows[i];
    const Rates q = rates_against_dofs ? dof_rates_at(rows, i) : rates_at(rows, i);
    auto e = [](std::optional<double> v) { return v ? table_number(v, "%.3e") : std::string("-"); };
    auto k = [&](std::optional<double> v, const std::vector<bool>& at_floor) {
      return v ? table_number(v, "%.2f") + (at_floor[i] ? "*" : "") : std::string("");
    };
    std::snprintf(line, sizeof line, "%5d %10.4e %8d %11s %6s %11s %6s %11s %6s %8.3fs %8.3fs %8.3fs %8.3fs", r.level,
                  r.h, r.dofs, e(r.l2).c_str(), k(q.l2, floor.l2).c_str(), e(r.h1).c_str(), k(q.h1, floor.h1).c_str(),
                  e(r.h2).c_str(), k(q.h2, floor.h2).c_str(), r.t_space, r.t_assemble, r.t_solve, r.t_errors);
    s << line;
    if (jumps) s << "  " << e(r.g1_jump);
    s << '\n';
  }
  if (floor.any()) s << "* round-off floor: the error stopped decreasing; left out of the least-squares rates\n";
  return s.str();
}

std::string summary_json(const StudySettings& settings, const StudyResult& result) {
  using nlohmann::json;
  json j;
  j["iga_run_version"] = IGA_RUN_VERSION;
  j["config"] = to_json(settings.root.yaml());
  j["config_file"] = settings.root.file();
  json space = {{"type", result.space_type}};
  for (const auto& [k, v] : result.space_parameters) space["parameters"][k] = v;
  j["space"] = space;
  if (result.surface) j["surface"] = surface_report_json(*result.surface);
  j["problem"] = {{"pde", to_string(settings.problem.pde)},
                  {"exact", settings.problem.exact ? json(settings.problem.exact->str()) : json(nullptr)},
                  {"source", settings.problem.source.str()}};
  if (settings.problem.surface_exact) j["problem"]["exact"] = settings.problem.surface_exact->str();
  if (settings.problem.surface_source) j["problem"]["source"] = settings.problem.surface_source->str();
  if (const std::string form = form_as_configured(settings.problem); !form.empty()) j["problem"]["form"] = form;
  for (const BoundaryPart& p : settings.problem.boundary) j["problem"]["boundary"][p.name] = to_string(p.kind);
  j["norms"] = "l2: L2 norm; h1: H1 seminorm |e|_1 = ||grad e||; h2: H2 seminorm |e|_2 = ||D^2 e|| (Frobenius)";
  json levels = json::array();
  std::vector<double> h, inverse_dofs;
  std::vector<std::optional<double>> l2, h1, h2;
  for (std::size_t i = 0; i < result.rows.size(); ++i) {
    const LevelResult& r = result.rows[i];
    const Rates q = rates_at(result.rows, i);
    const Rates d = dof_rates_at(result.rows, i);
    const Rates dr = difference_rates_at(result.rows, i, result.adaptive);
    levels.push_back({{"level", r.level},
                      {"h", r.h},
                      {"dofs", r.dofs},
                      {"free_dofs", r.free_dofs},
                      {"elements", r.elements},
                      {"l2", optional_json(r.l2)},
                      {"h1", optional_json(r.h1)},
                      {"h2", optional_json(r.h2)},
                      {"rate_l2", optional_json(q.l2)},
                      {"rate_h1", optional_json(q.h1)},
                      {"rate_h2", optional_json(q.h2)},
                      {"solver", result.solves[i].method},
                      {"relative_residual", result.solves[i].relative_residual},
                      {"refinement_steps", result.solves[i].refinement_steps},
                      {"g1_jump", optional_json(r.g1_jump)},
                      {"rate_dofs_l2", optional_json(d.l2)},
                      {"rate_dofs_h1", optional_json(d.h1)},
                      {"rate_dofs_h2", optional_json(d.h2)},
                      {"estimator", i < result.estimators.size() ? optional_json(result.estimators[i]) : json(nullptr)},
                      {"energy", optional_json(r.energy)},
                      {"energy_difference", optional_json(r.energy_difference)},
                      {"difference", {{"l2", optional_json(r.difference_l2)},
                                      {"h1", optional_json(r.difference_h1)},
                                      {"h2", optional_json(r.difference_h2)},
                                      {"rate_l2", optional_json(dr.l2)},
                                      {"rate_h1", optional_json(dr.h1)},
                                      {"rate_h2", optional_json(dr.h2)}}},
                      {"timings", {{"space", r.t_space}, {"assemble", r.t_assemble}, {"solve", r.t_solve},
                                   {"errors", r.t_errors}}}});
    if (!r.notes.empty()) levels.back()["notes"] = r.notes;
    h.push_back(r.h);
    inverse_dofs.push_back(1.0 / r.dofs);
    l2.push_back(r.l2);
    h1.push_back(r.h1);
    h2.push_back(r.h2);
  }
  // Functionals per level with their Richardson orders.
  const std::vector<double> hs = mesh_sizes(result.rows);
  for (std::size_t k = 0; k < settings.functionals.size(); ++k) {
    const std::vector<double> v = functional_values(result.rows, k);
    for (std::size_t i = 0; i < levels.size(); ++i)
      levels[i]["functionals"][settings.functionals[k].name] = {{"value", v[i]},
                                                               {"order", optional_json(richardson_order(v, hs, i))}};
  }
  j["levels"] = levels;
  const RoundOffFloor floor = round_off_levels(result.rows, result.adaptive);
  j["least_squares_rates"] = {{"l2", optional_json(least_squares_rate(h, l2, floor.l2))},
                              {"h1", optional_json(least_squares_rate(h, h1, floor.h1))},
                              {"h2", optional_json(least_squares_rate(h, h2, floor.h2))}};
  // Levels at the round-off floor, per norm: left out of both least-squares fits.
  auto floor_levels = [&](const std::vector<bool>& f) {
    json levels_at_floor = json::array();
    for (std::size_t i = 0; i < f.size(); ++i)
      if (f[i]) levels_at_floor.push_back(result.rows[i].level);
    return levels_at_floor;
  };
  j["round_off_floor"] = {{"l2", floor_levels(floor.l2)},
                          {"h1", floor_levels(floor.h1)},
                          {"h2", floor_levels(floor.h2)},
                          {"excluded_from_least_squares", true}};
  // e ~ N^(-rate): the slope against 1/N.
  j["least_squares_rates_dofs"] = {{"l2", optional_json(least_squares_rate(inverse_dofs, l2, floor.l2))},
                                   {"h1", optional_json(least_squares_rate(inverse_dofs, h1, floor.h1))},
                                   {"h2", optional_json(least_squares_rate(inverse_dofs, h2, floor.h2))}};
  j["refinement"] = result.adaptive ? "adaptive" : "uniform";
  if (!result.stop_reason.empty()) j["adaptive_stop_reason"] = result.stop_reason;
  // Rates are expected of errors against an exact solution; without one there is no such claim.
  if (has_errors(result.rows))
    j["expected_rates"] = {{"l2", result.expected.l2}, {"h1", result.expected.h1}, {"h2", result.expected.h2}};
  else
    j["expected_rates"] = nullptr;
  double total = result.t_vtk;
  for (const LevelResult& r : result.rows) total += r.t_space + r.t_assemble + r.t_solve + r.t_errors;
  j["t_vtk"] = result.t_vtk;
  // The whole run as its caller measured it (reading the config to the last file), else the phases' sum.
  j["total_seconds"] = result.total_seconds > 0 ? result.total_seconds : total;
  j["processes"] = {{"ranks", result.ranks}, {"threads_per_rank", result.threads}};
  // Text was checked to be UTF-8 where it was read; a path from the command line (a file name is
  // bytes) may still not be: replaced, never an exception after the study.
  if (settings.problem.eigen) {
    j["problem"]["eigen"] = {{"count", settings.problem.eigen->count}, {"spectrum", settings.problem.eigen->spectrum}};
    j["eigenvalues"] = eigen_json(eigen_rows(result.eigen, settings.problem.eigen->exact));
  }
  return j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace);
}

void write_summary_json(const StudySettings& settings, const StudyResult& result, const std::string& filename) {
  std::ofstream out = open_for_writing(filename);
  out << summary_json(settings, result) << '\n';
}

nlohmann::json config_as_json(const ConfigNode& root) { return to_json(root.yaml()); }

}  // namespace iga
