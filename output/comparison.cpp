#include "output/comparison.hpp"

#include <plplot/plstream.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace iga {

namespace {

std::optional<double> error_of(const LevelResult& row, ComparedNorm norm) {
  switch (norm) {
    case ComparedNorm::l2: return row.l2;
    case ComparedNorm::h1: return row.h1;
    case ComparedNorm::h2: return row.h2;
  }
  return std::nullopt;
}

const char* norm_name(ComparedNorm norm) {
  return norm == ComparedNorm::l2 ? "L2" : norm == ComparedNorm::h1 ? "|e|_H1" : "|e|_H2";
}

std::string csv_number(std::optional<double> v) {
  if (!v) return "";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10e", *v);
  return buf;
}

}  // namespace

std::optional<ComparedNorm> compared_norm(const std::vector<ComparedStudy>& studies) {
  for (ComparedNorm norm : {ComparedNorm::h2, ComparedNorm::h1, ComparedNorm::l2}) {
    bool all = !studies.empty();
    for (const ComparedStudy& s : studies) {
      const bool measured = std::any_of(s.result.rows.begin(), s.result.rows.end(),
                                        [&](const LevelResult& r) { return error_of(r, norm).has_value(); });
      all = all && measured;
    }
    if (all) return norm;
  }
  return std::nullopt;
}

double solution_seconds(const LevelResult& row) { return row.t_space + row.t_assemble + row.t_solve; }

void write_comparison_csv(const std::vector<ComparedStudy>& studies, const std::string& filename) {
  std::ofstream out(filename);
  if (!out) throw std::runtime_error("cannot write " + filename);
  out << "space,level,h,dofs,l2,h1,h2,t_solution,t_errors\n";
  for (const ComparedStudy& s : studies)
    for (const LevelResult& r : s.result.rows)
      out << s.label << ',' << r.level << ',' << csv_number(r.h) << ',' << r.dofs << ',' << csv_number(r.l2) << ','
          << csv_number(r.h1) << ',' << csv_number(r.h2) << ',' << csv_number(solution_seconds(r)) << ','
          << csv_number(r.t_errors) << '\n';
  if (!out) throw std::runtime_error("cannot write " + filename);
}

std::string format_reach_table(const std::vector<ComparedStudy>& studies, ComparedNorm norm) {
  // Decades from the largest first-level error down to the smallest error any space reached.
  double top = 0, bottom = HUGE_VAL;
  for (const ComparedStudy& s : studies)
    for (const LevelResult& r : s.result.rows)
      if (auto e = error_of(r, norm); e && *e > 0) top = std::max(top, *e), bottom = std::min(bottom, *e);
  std::ostringstream out;
  if (!(top > 0)) return out.str();
  const int k_hi = static_cast<int>(std::floor(std::log10(top))), k_lo = static_cast<int>(std::ceil(std::log10(bottom)));
  char line[256];
  std::snprintf(line, sizeof line, "DOFs and time (space + assembly + solve) to reach %s <= target\n%-16s",
                norm_name(norm), "space");
  out << line;
  for (int k = k_hi; k >= k_lo; --k) {
    std::snprintf(line, sizeof line, " %20s", ("<= 1e" + std::to_string(k)).c_str());
    out << line;
  }
  out << '\n';
  for (const ComparedStudy& s : studies) {
    std::snprintf(line, sizeof line, "%-16s", s.label.c_str());
    out << line;
    for (int k = k_hi; k >= k_lo; --k) {
      const double target = std::pow(10.0, k) * (1 + 1e-12);
      std::string cell = "-";
      for (const LevelResult& r : s.result.rows)
        if (auto e = error_of(r, norm); e && *e <= target) {
          char buf[64];
          std::snprintf(buf, sizeof buf, "%d / %.3fs", r.dofs, solution_seconds(r));
          cell = buf;
          break;
        }
      std::snprintf(line, sizeof line, " %20s", cell.c_str());
      out << line;
    }
    out << '\n';
  }
  return out.str();
}

void plot_comparison(const std::vector<ComparedStudy>& studies, ComparedNorm norm, const std::string& title,
                     const std::string& filename) {
  struct Line {
    std::string label;
    std::vector<PLFLT> log_dofs, log_time, log_e;
  };
  std::vector<Line> lines;
  for (const ComparedStudy& s : studies) {
    Line line{s.label, {}, {}, {}};
    for (const LevelResult& r : s.result.rows) {
      const auto e = error_of(r, norm);
      const double t = solution_seconds(r);
      if (!e || !(*e > 0) || !std::isfinite(*e) || r.dofs <= 0) continue;
      line.log_dofs.push_back(std::log10(static_cast<double>(r.dofs)));
      line.log_time.push_back(std::log10(std::max(t, 1e-4)));  // sub-0.1 ms levels sit at the axis floor
      line.log_e.push_back(std::log10(*e));
    }
    if (!line.log_e.empty()) lines.push_back(std::move(line));
  }
  if (lines.empty()) return;
  if (!std::ofstream(filename)) throw std::runtime_error("cannot write comparison plot '" + filename + "'");

  auto range = [](const std::vector<Line>& ls, std::vector<PLFLT> Line::*member) {
    double lo = HUGE_VAL, hi = -HUGE_VAL;
    for (const Line& l : ls)
      for (PLFLT v : l.*member) lo = std::min(lo, v), hi = std::max(hi, v);
    if (hi - lo < 1e-3) lo -= 0.5, hi += 0.5;
    const double pad = 0.06 * (hi - lo);
    return std::pair<double, double>{lo - pad, hi + pad};
  };
  const auto [ylo, yhi_data] = range(lines, &Line::log_e);
  const double yhi = yhi_data + 0.25 * (yhi_data - ylo);  // room for the legend
  const char* symbols[] = {"●", "■", "▲", "◆", "▼", "★"};
  const int colours[][3] = {{31, 119, 180}, {214, 39, 40}, {44, 160, 44}, {148, 103, 189}, {255, 127, 14}, {23, 190, 207}};

  PLINT error_code = 0;
  char error_message[256] = "";
  {
    plstream pls;
    pls.sError(&error_code, error_message);
    pls.sdev("svg");
    pls.sfnam(filename.c_str());
    pls.spage(0, 0, 1200, 520, 0, 0);
    pls.ssub(2, 1);
    pls.scolbg(255, 255, 255);
    pls.scol0(1, 0, 0, 0);
    for (int i = 0; i < 6; ++i) pls.scol0(2 + i, colours[i][0], colours[i][1], colours[i][2]);
    pls.init();
    pls.schr(0, 0.85);
    for (int panel = 0; panel < 2; ++panel) {
      const auto member = panel == 0 ? &Line::log_dofs : &Line::log_time;
      const auto [xlo, xhi] = range(lines, member);
      pls.col0(1);
      pls.env(xlo, xhi, ylo, yhi, 0, 30);
      const std::string y_label = std::string(norm_name(norm)) + " error";
      pls.lab(panel == 0 ? "degrees of freedom" : "time to solution (s)", y_label.c_str(), title.c_str());
      std::vector<std::string> texts;
      std::vector<PLINT> opts, text_colours, line_colours, line_styles, symbol_colours, symbol_numbers;
      std::vector<PLFLT> line_widths, symbol_scales;
      std::vector<const char*> symbol_ptrs, text_ptrs;
      for (std::size_t i = 0; i < lines.size(); ++i) {
        const Line& l = lines[i];
        const int colour = 2 + static_cast<int>(i % 6);
        const auto& xs = l.*member;
        pls.col0(colour);
        pls.width(2.0);
        pls.line(static_cast<PLINT>(xs.size()), xs.data(), l.log_e.data());
        pls.schr(0, 0.5);
        pls.string(static_cast<PLINT>(xs.size()), xs.data(), l.log_e.data(), symbols[i % 6]);
        pls.schr(0, 0.85);
        texts.push_back(l.label);
        opts.push_back(PL_LEGEND_LINE | PL_LEGEND_SYMBOL);
        text_colours.push_back(1);
        line_colours.push_back(colour);
        line_styles.push_back(1);
        line_widths.push_back(2.0);
        symbol_colours.push_back(colour);
        symbol_numbers.push_back(1);
        symbol_scales.push_back(0.6);
        symbol_ptrs.push_back(symbols[i % 6]);
      }
      for (const std::string& t : texts) text_ptrs.push_back(t.c_str());
      PLFLT w = 0, h = 0;
      pls.legend(&w, &h, PL_LEGEND_BACKGROUND | PL_LEGEND_BOUNDING_BOX,
                 PL_POSITION_TOP | PL_POSITION_INSIDE | PL_POSITION_RIGHT, 0.02, 0.02, 0.08, 0, 1, 1, 0, 0,
                 static_cast<PLINT>(texts.size()), opts.data(), 1.0, 0.8, 1.6, 0.0, text_colours.data(),
                 text_ptrs.data(), nullptr, nullptr, nullptr, nullptr, line_colours.data(), line_styles.data(),
                 line_widths.data(), symbol_colours.data(), symbol_scales.data(), symbol_numbers.data(),
                 symbol_ptrs.data());
      pls.width(1.0);
    }
  }
  if (error_code != 0) {
    if (std::filesystem::is_regular_file(filename)) std::filesystem::remove(filename);
    throw std::runtime_error("comparison plot '" + filename + "': PLplot: " + error_message);
  }
}

}  // namespace iga
