#include "output/convergence_plot.hpp"

#include <plplot/plstream.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <stdexcept>

#include "output/plot_colours.hpp"
#include "output/report.hpp"

namespace iga {

namespace {

// Character height relative to PLplot's default, and of the data symbols relative to text.
constexpr PLFLT kTextScale = 0.85, kSymbolScale = 0.6;

/// One error norm: its points in log10 coordinates and the slope (in h) it should show.
struct Series {
  const char* label;
  std::optional<double> LevelResult::*error;
  int colour;
  const char* symbol;
  int expected_rate;
  std::vector<PLFLT> log_time, log_dofs, log_e;
  std::vector<bool> at_floor;  ///< per point: at the round-off floor (drawn apart, not fitted)
};

/// Min and max of `values`, widened so PLplot gets a non-degenerate window with a margin.
std::pair<PLFLT, PLFLT> padded_range(const std::vector<PLFLT>& values, double margin) {
  auto [lo, hi] = std::minmax_element(values.begin(), values.end());
  double a = *lo, b = *hi;
  if (b - a < 1e-3) a -= 0.5, b += 0.5;  // a single level: show one decade around it
  const double pad = margin * (b - a);
  return {a - pad, b + pad};
}

/// Exponent text for PLplot: "3", "3/2".
std::string half_power(int k) { return k % 2 == 0 ? std::to_string(k / 2) : std::to_string(k) + "/2"; }

/// One panel: the series against x (log10 DOFs or log10 seconds). Against DOFs, a dashed
/// reference slope DOF^(-rate/2) per series starts just below the data at its finest clean level
/// and runs back over the last levels, so it reads against the points it should match.
void draw_panel(plstream& pls, const std::vector<Series>& series, bool against_dofs, const std::string& title) {
  auto xs_of = [&](const Series& s) -> const std::vector<PLFLT>& { return against_dofs ? s.log_dofs : s.log_time; };

  struct Line {
    std::vector<PLFLT> x, y;
  };
  std::vector<std::optional<Line>> reference(series.size());
  std::vector<PLFLT> all_x, all_y;
  for (std::size_t i = 0; i < series.size(); ++i) {
    const Series& s = series[i];
    const auto& xs = xs_of(s);
    all_x.insert(all_x.end(), xs.begin(), xs.end());
    all_y.insert(all_y.end(), s.log_e.begin(), s.log_e.end());
    if (!against_dofs || s.expected_rate <= 0) continue;
    // The finest level that is not at the round-off floor, and up to two levels before it.
    int last = static_cast<int>(xs.size()) - 1;
    while (last >= 0 && s.at_floor[last]) --last;
    if (last < 1) continue;  // a slope needs two levels
    const int first = std::max(0, last - 2);
    const double slope = -0.5 * s.expected_rate;
    const PLFLT x0 = xs[last], y0 = s.log_e[last] - 0.15;
    Line line;
    for (PLFLT x : {xs[first], x0}) {
      line.x.push_back(x);
      line.y.push_back(y0 + slope * (x - x0));
    }
    all_y.insert(all_y.end(), line.y.begin(), line.y.end());
    reference[i] = std::move(line);
  }
  auto [xmin, xmax] = padded_range(all_x, 0.08);
  auto [ymin, ymax] = padded_range(all_y, 0.05);
  ymax += 0.3 * (ymax - ymin);  // headroom for the legend above the data

  pls.col0(kPlotInk);
  pls.lsty(1);
  pls.width(1.0);
  pls.env(xmin, xmax, ymin, ymax, 0, 30);  // 30: logarithmic x and y axes
  pls.lab(against_dofs ? "degrees of freedom" : "time to solution: space + assembly + solve (s)", "error",
          title.c_str());

  std::vector<std::string> texts;
  std::vector<PLINT> opts, text_colours, line_colours, line_styles, symbol_colours, symbol_numbers;
  std::vector<PLFLT> line_widths, symbol_scales;
  std::vector<const char*> symbols;
  auto add_entry = [&](std::string text, PLINT opt, int colour, PLINT style, const char* symbol) {
    texts.push_back(std::move(text));
    opts.push_back(opt);
    text_colours.push_back(kPlotInk);
    line_colours.push_back(colour);
    line_styles.push_back(style);
    line_widths.push_back(style == 1 ? 2.0 : 1.5);
    symbol_colours.push_back(colour);
    symbol_numbers.push_back(1);
    symbol_scales.push_back(kSymbolScale);
    symbols.push_back(symbol);
  };
  for (std::size_t i = 0; i < series.size(); ++i) {
    const Series& s = series[i];
    const auto& xs = xs_of(s);
    if (xs.empty()) continue;
    const auto n = static_cast<PLINT>(xs.size());
    pls.col0(s.colour);
    pls.width(2.0);
    pls.lsty(1);
    pls.line(n, xs.data(), s.log_e.data());
    pls.schr(0, kSymbolScale * kTextScale);
    std::vector<PLFLT> clean_x, clean_y, floor_x, floor_y;
    for (std::size_t k = 0; k < xs.size(); ++k) {
      (s.at_floor[k] ? floor_x : clean_x).push_back(xs[k]);
      (s.at_floor[k] ? floor_y : clean_y).push_back(s.log_e[k]);
    }
    pls.string(static_cast<PLINT>(clean_x.size()), clean_x.data(), clean_y.data(), s.symbol);
    if (!floor_x.empty()) pls.string(static_cast<PLINT>(floor_x.size()), floor_x.data(), floor_y.data(), "○");
    pls.schr(0, kTextScale);
    add_entry(s.label, PL_LEGEND_LINE | PL_LEGEND_SYMBOL, s.colour, 1, s.symbol);
    if (!floor_x.empty()) add_entry(std::string(s.label) + ": round-off floor", PL_LEGEND_SYMBOL, s.colour, 1, "○");
  }
  for (std::size_t i = 0; i < series.size(); ++i) {
    if (!reference[i]) continue;
    const Series& s = series[i];
    pls.col0(s.colour);
    pls.width(1.5);
    pls.lsty(2);  // dashed
    pls.line(2, reference[i]->x.data(), reference[i]->y.data());
    const std::string text = "DOF#u-" + half_power(s.expected_rate) + "#d  (h#u" + std::to_string(s.expected_rate) + "#d)";
    add_entry(text, PL_LEGEND_LINE, s.colour, 2, "");
  }
  pls.lsty(1);
  pls.width(1.0);

  std::vector<const char*> text_ptrs;
  for (const std::string& t : texts) text_ptrs.push_back(t.c_str());
  // Data rise to the right against h and fall against DOFs: keep the legend in the emptier corner.
  const PLINT position = PL_POSITION_TOP | PL_POSITION_INSIDE | (against_dofs ? PL_POSITION_RIGHT : PL_POSITION_LEFT);
  PLFLT legend_width = 0, legend_height = 0;
  pls.legend(&legend_width, &legend_height, PL_LEGEND_BACKGROUND | PL_LEGEND_BOUNDING_BOX, position, 0.02, 0.02,
             0.08, kPlotBackground, kPlotInk, 1, 0, 0, static_cast<PLINT>(texts.size()), opts.data(), 1.0, 0.8, 1.6, 0.0,
             text_colours.data(), text_ptrs.data(), nullptr, nullptr, nullptr, nullptr, line_colours.data(),
             line_styles.data(), line_widths.data(), symbol_colours.data(), symbol_scales.data(),
             symbol_numbers.data(), symbols.data());
}

}  // namespace

void plot_convergence(const std::vector<LevelResult>& rows, const OptimalRates& expected, const std::string& title,
                      const std::string& filename, bool adaptive) {
  std::vector<Series> series = {
      {"||e||#dL2#u", &LevelResult::l2, 2, "●", expected.l2, {}, {}, {}, {}},
      {"|e|#dH1#u", &LevelResult::h1, 3, "■", expected.h1, {}, {}, {}, {}},
      {"|e|#dH2#u", &LevelResult::h2, 4, "▲", expected.h2, {}, {}, {}, {}},
  };
  const RoundOffFloor floor = round_off_levels(rows, adaptive);
  const std::vector<bool>* floors[] = {&floor.l2, &floor.h1, &floor.h2};
  bool any = false;
  for (std::size_t n = 0; n < series.size(); ++n) {
    Series& s = series[n];
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const LevelResult& row = rows[i];
      const std::optional<double>& e = row.*s.error;
      // Log axes: a zero error (exact reproduction) has no place on them.
      if (!e || !(*e > 0) || !std::isfinite(*e) || row.dofs <= 0) continue;
      s.log_dofs.push_back(std::log10(static_cast<double>(row.dofs)));
      // Levels faster than 0.1 ms sit at the axis floor.
      s.log_time.push_back(std::log10(std::max(1e-4, row.t_space + row.t_assemble + row.t_solve)));
      s.log_e.push_back(std::log10(*e));
      s.at_floor.push_back((*floors[n])[i]);
      any = true;
    }
  }
  const auto collect = [&](Series& d) {
    for (const LevelResult& row : rows) {
      const std::optional<double>& e = row.*d.error;
      if (!e || !(*e > 0) || !std::isfinite(*e) || row.dofs <= 0) continue;
      d.log_dofs.push_back(std::log10(static_cast<double>(row.dofs)));
      d.log_time.push_back(std::log10(std::max(1e-4, row.t_space + row.t_assemble + row.t_solve)));
      d.log_e.push_back(std::log10(*e));
      d.at_floor.push_back(false);
    }
    return !d.log_e.empty();
  };
  if (!any) {
    // No exact solution: the differences between successive levels show the convergence (no
    // reference slopes: nothing is claimed), else the energy-norm change.
    std::vector<Series> differences = {
        {"||u#dl#u-u#dl-1#u||#dL2#u", &LevelResult::difference_l2, 2, "●", 0, {}, {}, {}, {}},
        {"|u#dl#u-u#dl-1#u|#dH1#u", &LevelResult::difference_h1, 3, "■", 0, {}, {}, {}, {}},
        {"|u#dl#u-u#dl-1#u|#dH2#u", &LevelResult::difference_h2, 4, "▲", 0, {}, {}, {}, {}},
    };
    series.clear();
    for (Series& d : differences)
      if (collect(d)) series.push_back(d);
    if (series.empty()) {
      Series d{"|u#dl#u-u#dl-1#u|#da#u", &LevelResult::energy_difference, 2, "●", 0, {}, {}, {}, {}};
      if (!collect(d)) return;
      series = {d};
    }
  }

  // PLplot exits the process when it cannot open its output file, so find out first.
  if (!std::ofstream(filename)) throw std::runtime_error("cannot write convergence plot '" + filename + "'");

  PLINT error_code = 0;
  char error_message[256] = "";  // PLplot needs >= 160 bytes
  {
    plstream pls;
    pls.sError(&error_code, error_message);  // collect errors here instead of printing them
    pls.sdev("svg");
    pls.sfnam(filename.c_str());
    pls.spage(0, 0, 1200, 520, 0, 0);
    pls.ssub(2, 1);
    pls.scolbg(255, 255, 255);
    pls.scol0(kPlotInk, 0, 0, 0);
    pls.scol0(2, 31, 119, 180);   // blue
    pls.scol0(3, 214, 39, 40);    // red
    pls.scol0(4, 44, 160, 44);    // green
    pls.init();
    pls.schr(0, kTextScale);
    draw_panel(pls, series, true, title);
    draw_panel(pls, series, false, title);
  }  // ~plstream ends the stream and closes the file
  if (error_code != 0) {
    if (std::filesystem::is_regular_file(filename)) std::filesystem::remove(filename);  // no half-written output
    throw std::runtime_error("convergence plot '" + filename + "': PLplot: " + error_message);
  }
  std::error_code ec;
  if (std::filesystem::file_size(filename, ec) == 0 || ec)
    throw std::runtime_error("cannot write convergence plot '" + filename + "'");
}

}  // namespace iga
