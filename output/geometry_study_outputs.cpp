#include "output/geometry_study_outputs.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "output/report.hpp"
#include "output/surface_files.hpp"
#include "output/surface_report.hpp"

namespace iga {

namespace {

/// log(e_{l−1}/e_l) / log(h_{l−1}/h_l); none at level 0 or for a zero error.
std::optional<double> rate(const std::vector<GeometryLevel>& rows, std::size_t i, double GeometryLevel::*error) {
  if (i == 0) return std::nullopt;
  const double e0 = rows[i - 1].*error, e1 = rows[i].*error;
  if (!(e0 > 0 && e1 > 0)) return std::nullopt;
  return std::log(e0 / e1) / std::log(rows[i - 1].h / rows[i].h);
}

double measure(const GeometryLevel& row, const std::string& key) {
  for (const auto& [k, v] : row.patches.measures)
    if (k == key) return v;
  return std::nan("");
}

struct Column {
  const char* name;
  double GeometryLevel::*error;
};
const Column columns[] = {{"radial", &GeometryLevel::radial},
                          {"normal_degrees", &GeometryLevel::normal_degrees},
                          {"area", &GeometryLevel::area_error},
                          {"volume", &GeometryLevel::volume_error}};

void write_csv(const std::vector<GeometryLevel>& rows, const std::string& filename) {
  std::ofstream out(filename);
  out << "level,triangles,h";
  for (const Column& c : columns) out << "," << c.name << ",rate_" << c.name;
  out << ",max_g1_residual,max_fold_alpha,min_regularity,interpolation_residual\n";
  out.precision(10);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const GeometryLevel& r = rows[i];
    out << r.level << "," << r.triangles << "," << r.h;
    for (const Column& c : columns) {
      const auto q = rate(rows, i, c.error);
      out << "," << r.*c.error << ",";
      if (q) out << *q;
    }
    for (const char* key : {"max_g1_residual", "max_fold_alpha", "min_regularity", "interpolation_residual"})
      out << "," << measure(r, key);
    out << "\n";
  }
  if (!out) throw std::runtime_error("cannot write " + filename);
}

void write_summary(const GeometryStudySettings& settings, const std::vector<GeometryLevel>& rows,
                   const std::vector<std::vector<std::string>>& files, const std::string& filename) {
  using nlohmann::json;
  json j;
  j["iga_run_version"] = IGA_RUN_VERSION;
  j["config"] = config_as_json(settings.root);
  j["config_file"] = settings.root.file();
  j["study"] = "geometry";
  j["reference"] = {{"type", "sphere"},
                    {"center", {settings.center.x(), settings.center.y(), settings.center.z()}},
                    {"radius", settings.radius}};
  j["errors"] =
      "radial: max ||F - c| - r|; normal_degrees: max angle between the surface normal and F - c; area, volume: "
      "relative errors against the sphere's";
  json levels = json::array();
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const GeometryLevel& r = rows[i];
    json level = {{"level", r.level}, {"triangles", r.triangles}, {"h", r.h}};
    for (const Column& c : columns) {
      level[c.name] = r.*c.error;
      const auto q = rate(rows, i, c.error);
      level[std::string("rate_") + c.name] = q ? json(*q) : json(nullptr);
    }
    level["surface"] = surface_report_json(r.patches);
    level["files"] = files[i];
    levels.push_back(level);
  }
  j["levels"] = levels;
  std::ofstream out(filename);
  out << j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";  // never throws on bytes that are not UTF-8
  if (!out) throw std::runtime_error("cannot write " + filename);
}

}  // namespace

std::vector<GeometryLevel> run_geometry_study_with_files(const GeometryStudySettings& settings,
                                                         const std::string& directory,
                                                         const std::function<void(const std::string&)>& progress) {
  std::vector<std::vector<std::string>> files;
  const auto write_level = [&](const GeometryLevel& row) {
    const bool wanted = settings.surface_files_up_to_level < 0 || row.level <= settings.surface_files_up_to_level;
    files.push_back(wanted ? write_surface_files(row.patches, directory, "surface_" + std::to_string(row.level),
                                                 settings.vtk_samples, settings.write_vtk)
                           : std::vector<std::string>{});
  };
  const std::vector<GeometryLevel> rows = run_geometry_study(settings, progress, write_level);
  const std::filesystem::path dir(directory);
  write_csv(rows, (dir / "geometry.csv").string());
  write_summary(settings, rows, files, (dir / "summary.json").string());
  return rows;
}

std::string format_geometry_table(const std::vector<GeometryLevel>& rows) {
  std::ostringstream s;
  char line[256];
  std::snprintf(line, sizeof line, "%5s %9s %8s %10s %5s %10s %5s %10s %5s %10s %5s %9s\n", "level", "triangles", "h",
                "radial", "rate", "normal(°)", "rate", "area", "rate", "volume", "rate", "G1");
  s << line;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const GeometryLevel& r = rows[i];
    s << [&] {
      std::snprintf(line, sizeof line, "%5d %9d %8.4f", r.level, r.triangles, r.h);
      return std::string(line);
    }();
    for (const Column& c : columns) {
      const auto q = rate(rows, i, c.error);
      char rate_text[16] = "";
      if (q) std::snprintf(rate_text, sizeof rate_text, "%.2f", *q);
      std::snprintf(line, sizeof line, " %10.3e %5s", r.*c.error, rate_text);
      s << line;
    }
    std::snprintf(line, sizeof line, " %9.1e\n", measure(r, "max_g1_residual"));
    s << line;
  }
  return s.str();
}

}  // namespace iga
