#include "output/eigen_report.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <stdexcept>

#include "output/eigen_plot.hpp"
#include "output/table_values.hpp"

namespace iga {

void write_eigenvalues_csv(const std::vector<EigenRow>& rows, const std::string& filename) {
  std::ofstream out(filename);
  if (!out) throw std::runtime_error("cannot write " + filename);
  out << "level,h,dofs,index,eigenvalue,reference,relative_error,rate,rate_dofs\n";
  for (const EigenRow& r : rows)
    out << r.level << ',' << table_number(r.h, "%.10e") << ',' << r.dofs << ',' << r.index << ','
        << table_number(r.eigenvalue, "%.17e") << ',' << table_number(r.reference, "%.17e") << ','
        << table_number(r.relative_error, "%.6e") << ',' << table_number(r.rate, "%.4f") << ',' << table_number(r.rate_dofs, "%.4f")
        << '\n';
}

std::string format_eigen_table(const std::vector<EigenRow>& rows) {
  std::vector<EigenRow> sorted = rows;
  std::stable_sort(sorted.begin(), sorted.end(), [](const EigenRow& a, const EigenRow& b) { return a.index < b.index; });
  const bool references = std::any_of(rows.begin(), rows.end(), [](const EigenRow& r) { return r.reference.has_value(); });
  std::string out;
  char line[256];
  std::snprintf(line, sizeof line, "%5s %5s %8s %24s", "index", "level", "dofs", "eigenvalue");
  out += line;
  if (references) {
    std::snprintf(line, sizeof line, " %24s %12s %7s %7s", "reference", "rel. error", "rate h", "rate N");
    out += line;
  }
  out += '\n';
  for (const EigenRow& r : sorted) {
    std::snprintf(line, sizeof line, "%5d %5d %8d %24.16e", r.index, r.level, r.dofs, r.eigenvalue);
    out += line;
    if (references && r.reference) {
      std::snprintf(line, sizeof line, " %24.16e %12.3e %7s %7s", *r.reference, *r.relative_error,
                    table_number(r.rate, "%.2f").c_str(), table_number(r.rate_dofs, "%.2f").c_str());
      out += line;
    }
    out += '\n';
  }
  return out;
}

namespace {
/// The references of a whole spectrum of N eigenvalues: the formula's N smallest, or the list.
std::vector<double> spectrum_references(const EigenSpec& spec, int N) {
  return spec.formula.empty() ? spec.exact : eigenvalues_from_formula(spec.formula, spec.formula_where, N);
}

/// The ratios of one level's rows, when every eigenvalue has a reference.
std::optional<std::vector<double>> all_ratios(const std::vector<SpectrumRow>& rows) {
  std::vector<double> ratios;
  for (const SpectrumRow& r : rows) {
    if (!r.ratio) return std::nullopt;
    ratios.push_back(*r.ratio);
  }
  return ratios;
}
}  // namespace

void write_spectrum_files(const EigenSpec& spec, const std::vector<EigenLevel>& levels, const std::string& directory,
                          const std::string& title, bool plot) {
  std::vector<SpectrumRow> rows;
  std::vector<SpectrumCurve> curves;
  for (const EigenLevel& level : levels) {
    const int N = static_cast<int>(level.spectrum.size());
    if (N == 0) continue;
    const std::vector<SpectrumRow> mine = spectrum_rows(level, spectrum_references(spec, N));
    rows.insert(rows.end(), mine.begin(), mine.end());
    if (auto ratios = all_ratios(mine))
      curves.push_back({"level " + std::to_string(level.level) + ", N = " + std::to_string(N), std::move(*ratios)});
  }
  if (rows.empty()) return;
  const std::string csv = directory + "/spectrum.csv";
  std::ofstream out(csv);
  if (!out) throw std::runtime_error("cannot write " + csv);
  out << "level,n,N,eigenvalue,reference,ratio\n";
  for (const SpectrumRow& r : rows)
    out << r.level << ',' << r.n << ',' << r.N << ',' << table_number(r.eigenvalue, "%.17e") << ','
        << table_number(r.reference, "%.17e") << ',' << table_number(r.ratio, "%.15f") << '\n';
  if (plot && !curves.empty()) plot_normalized_spectrum(curves, title, directory + "/spectrum.svg");
}

std::optional<SpectrumCurve> finest_normalized_spectrum(const EigenSpec& spec, const std::vector<EigenLevel>& levels,
                                                        const std::string& label) {
  for (auto level = levels.rbegin(); level != levels.rend(); ++level) {
    const int N = static_cast<int>(level->spectrum.size());
    if (N == 0) continue;
    if (auto ratios = all_ratios(spectrum_rows(*level, spectrum_references(spec, N))))
      return SpectrumCurve{label + ", N = " + std::to_string(N), std::move(*ratios)};
  }
  return std::nullopt;
}

std::string format_eigen_comparison(const std::vector<std::pair<std::string, std::vector<EigenRow>>>& spaces) {
  std::string out = "largest relative eigenvalue error per level (over the eigenvalues with references)\n";
  char line[160];
  std::snprintf(line, sizeof line, "%-16s %8s %12s\n", "space", "dofs", "error");
  out += line;
  for (const auto& [label, rows] : spaces)
    for (const auto& [dofs, error] : worst_relative_errors(rows)) {
      std::snprintf(line, sizeof line, "%-16s %8d %12.3e\n", label.c_str(), dofs, error);
      out += line;
    }
  return out;
}

nlohmann::json eigen_json(const std::vector<EigenRow>& rows) {
  nlohmann::json a = nlohmann::json::array();
  for (const EigenRow& r : rows)
    a.push_back({{"level", r.level},
                 {"h", r.h},
                 {"dofs", r.dofs},
                 {"index", r.index},
                 {"eigenvalue", r.eigenvalue},
                 {"reference", optional_json(r.reference)},
                 {"relative_error", optional_json(r.relative_error)},
                 {"rate", optional_json(r.rate)},
                 {"rate_dofs", optional_json(r.rate_dofs)}});
  return a;
}

}  // namespace iga
