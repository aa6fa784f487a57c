#include "output/eigen_plot.hpp"

#include <plplot/plstream.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <stdexcept>

#include "output/plot_colours.hpp"

namespace iga {

namespace {

constexpr int kColours = 6;

/// One SVG page drawn by `draw`, PLplot's errors turned into exceptions (and no half-written file).
void svg(const std::string& filename, const std::function<void(plstream&)>& draw) {
  // PLplot exits the process when it cannot open its output file, so find out first.
  if (!std::ofstream(filename)) throw std::runtime_error("cannot write plot '" + filename + "'");
  PLINT error_code = 0;
  char error_message[256] = "";  // PLplot needs >= 160 bytes
  {
    plstream pls;
    pls.sError(&error_code, error_message);
    pls.sdev("svg");
    pls.sfnam(filename.c_str());
    pls.spage(0, 0, 760, 560, 0, 0);
    pls.scolbg(255, 255, 255);
    pls.scol0(kPlotInk, 0, 0, 0);
    const int rgb[kColours][3] = {{31, 119, 180}, {214, 39, 40}, {44, 160, 44}, {148, 103, 189}, {255, 127, 14}, {23, 190, 207}};
    for (int c = 0; c < kColours; ++c) pls.scol0(2 + c, rgb[c][0], rgb[c][1], rgb[c][2]);
    pls.init();
    pls.schr(0, 0.85);
    draw(pls);
  }
  if (error_code != 0) {
    if (std::filesystem::is_regular_file(filename)) std::filesystem::remove(filename);
    throw std::runtime_error("plot '" + filename + "': PLplot: " + error_message);
  }
}

std::pair<PLFLT, PLFLT> range(const std::vector<PLFLT>& v, double margin) {
  auto [lo, hi] = std::minmax_element(v.begin(), v.end());
  double a = *lo, b = *hi;
  if (b - a < 1e-3) a -= 0.5, b += 0.5;
  return {a - margin * (b - a), b + margin * (b - a)};
}

/// A legend of lines at the top, inside, on the given side.
void legend(plstream& pls, const std::vector<std::string>& texts, std::vector<PLINT>& opts, std::vector<PLINT>& colours,
            std::vector<PLINT>& styles, PLINT side) {
  std::vector<const char*> text_ptrs;
  for (const std::string& t : texts) text_ptrs.push_back(t.c_str());
  std::vector<PLINT> text_colours(texts.size(), kPlotInk);
  std::vector<PLFLT> widths(texts.size(), 2.0);
  PLFLT w = 0, h = 0;
  pls.legend(&w, &h, PL_LEGEND_BACKGROUND | PL_LEGEND_BOUNDING_BOX, PL_POSITION_TOP | side | PL_POSITION_INSIDE, 0.02,
             0.02, 0.08, 0, kPlotInk, 1, 0, 0, static_cast<PLINT>(texts.size()), opts.data(), 1.0, 0.8, 1.6, 0.0,
             text_colours.data(), text_ptrs.data(), nullptr, nullptr, nullptr, nullptr, colours.data(), styles.data(),
             widths.data(), nullptr, nullptr, nullptr, nullptr);
}

}  // namespace

void plot_eigen_errors(const std::vector<EigenRow>& rows, int expected_rate, const std::string& title,
                       const std::string& filename) {
  // index -> points; a multiple eigenvalue (equal reference) is drawn for its first index only.
  std::map<int, std::pair<std::vector<PLFLT>, std::vector<PLFLT>>> lines;
  std::vector<double> drawn;
  for (const EigenRow& r : rows) {
    if (!r.relative_error || !(*r.relative_error > 0) || !std::isfinite(*r.relative_error)) continue;  // log scale
    const bool repeat = std::any_of(drawn.begin(), drawn.end(), [&](double v) {
      return std::abs(v - *r.reference) <= 1e-12 * std::abs(v);
    });
    if (repeat && !lines.count(r.index)) continue;
    if (!repeat) drawn.push_back(*r.reference);
    lines[r.index].first.push_back(std::log10(double(r.dofs)));
    lines[r.index].second.push_back(std::log10(*r.relative_error));
  }
  if (lines.empty()) return;
  std::vector<PLFLT> xs, ys;
  for (const auto& [index, l] : lines) {
    xs.insert(xs.end(), l.first.begin(), l.first.end());
    ys.insert(ys.end(), l.second.begin(), l.second.end());
  }
  svg(filename, [&](plstream& pls) {
    const auto [x0, x1] = range(xs, 0.08);
    auto [y0, y1] = range(ys, 0.05);
    y1 += 0.25 * (y1 - y0);
    pls.col0(kPlotInk);
    pls.env(x0, x1, y0, y1, 0, 30);
    pls.lab("degrees of freedom", "relative eigenvalue error", title.c_str());
    std::vector<std::string> texts;
    std::vector<PLINT> opts, colours, styles;
    int k = 0;
    for (const auto& [index, l] : lines) {
      const int colour = 2 + (k++ % kColours);
      pls.col0(colour);
      pls.width(2.0);
      pls.line(static_cast<PLINT>(l.first.size()), l.first.data(), l.second.data());
      pls.string(static_cast<PLINT>(l.first.size()), l.first.data(), l.second.data(), "●");
      texts.push_back("λ#d" + std::to_string(index) + "#u");
      opts.push_back(PL_LEGEND_LINE);
      colours.push_back(colour);
      styles.push_back(1);
      // The slope through the finest point of the first line, back over two levels.
      if (k == 1 && l.first.size() >= 2 && expected_rate > 0) {
        const std::size_t n = l.first.size();
        const PLFLT xa = l.first[n >= 3 ? n - 3 : 0], xb = l.first[n - 1], yb = l.second[n - 1] - 0.15;
        const PLFLT sx[2] = {xa, xb}, sy[2] = {yb - 0.5 * expected_rate * (xa - xb), yb};
        pls.col0(kPlotInk);
        pls.lsty(2);
        pls.line(2, sx, sy);
        pls.lsty(1);
        texts.push_back("DOF#u-" + std::to_string(expected_rate) + "/2#d (h#u" + std::to_string(expected_rate) + "#d)");
        opts.push_back(PL_LEGEND_LINE);
        colours.push_back(kPlotInk);
        styles.push_back(2);
      }
    }
    legend(pls, texts, opts, colours, styles, PL_POSITION_RIGHT);
  });
}

std::vector<std::pair<int, double>> worst_relative_errors(const std::vector<EigenRow>& rows) {
  std::map<int, std::pair<int, double>> by_level;
  for (const EigenRow& r : rows) {
    if (!r.relative_error) continue;
    auto& [dofs, worst] = by_level[r.level];
    dofs = r.dofs;
    worst = std::max(worst, *r.relative_error);
  }
  std::vector<std::pair<int, double>> out;
  for (const auto& [level, point] : by_level) out.push_back(point);
  return out;
}

void plot_eigen_comparison(const std::vector<std::pair<std::string, std::vector<EigenRow>>>& spaces,
                           const std::string& title, const std::string& filename) {
  std::vector<std::pair<std::string, std::pair<std::vector<PLFLT>, std::vector<PLFLT>>>> lines;
  std::vector<PLFLT> xs, ys;
  for (const auto& [label, rows] : spaces) {
    std::pair<std::vector<PLFLT>, std::vector<PLFLT>> line;
    for (const auto& [dofs, error] : worst_relative_errors(rows)) {
      if (!(error > 0) || !std::isfinite(error)) continue;  // log scale
      line.first.push_back(std::log10(double(dofs)));
      line.second.push_back(std::log10(error));
    }
    if (line.first.empty()) continue;
    xs.insert(xs.end(), line.first.begin(), line.first.end());
    ys.insert(ys.end(), line.second.begin(), line.second.end());
    lines.emplace_back(label, std::move(line));
  }
  if (lines.empty()) return;
  svg(filename, [&](plstream& pls) {
    const auto [x0, x1] = range(xs, 0.08);
    auto [y0, y1] = range(ys, 0.05);
    pls.col0(kPlotInk);
    pls.env(x0, x1, y0, y1 + 0.25 * (y1 - y0), 0, 30);
    pls.lab("degrees of freedom", "largest relative eigenvalue error", title.c_str());
    std::vector<std::string> texts;
    std::vector<PLINT> opts, colours, styles;
    for (std::size_t k = 0; k < lines.size(); ++k) {
      const auto& [label, l] = lines[k];
      const int colour = 2 + int(k % kColours);
      pls.col0(colour);
      pls.width(2.0);
      pls.line(static_cast<PLINT>(l.first.size()), l.first.data(), l.second.data());
      pls.string(static_cast<PLINT>(l.first.size()), l.first.data(), l.second.data(), "●");
      texts.push_back(label);
      opts.push_back(PL_LEGEND_LINE);
      colours.push_back(colour);
      styles.push_back(1);
    }
    legend(pls, texts, opts, colours, styles, PL_POSITION_RIGHT);
  });
}

void plot_normalized_spectrum(const std::vector<SpectrumCurve>& curves, const std::string& title,
                              const std::string& filename) {
  std::vector<PLFLT> ys{1.0};
  for (const SpectrumCurve& c : curves) ys.insert(ys.end(), c.ratios.begin(), c.ratios.end());
  svg(filename, [&](plstream& pls) {
    auto [y0, y1] = range(ys, 0.05);
    y0 = std::min<PLFLT>(y0, 0.95);
    pls.col0(kPlotInk);
    pls.env(0.0, 1.0, y0, y1 + 0.2 * (y1 - y0), 0, 0);
    pls.lab("n / N", "λ#dh,n#u / λ#dn#u", title.c_str());
    std::vector<std::string> texts;
    std::vector<PLINT> opts, colours, styles;
    for (std::size_t k = 0; k < curves.size(); ++k) {
      const std::vector<double>& r = curves[k].ratios;
      std::vector<PLFLT> x(r.size());
      for (std::size_t n = 0; n < r.size(); ++n) x[n] = double(n + 1) / double(r.size());
      const int colour = 2 + int(k % kColours);
      pls.col0(colour);
      pls.width(2.0);
      pls.line(static_cast<PLINT>(r.size()), x.data(), r.data());
      texts.push_back(curves[k].label);
      opts.push_back(PL_LEGEND_LINE);
      colours.push_back(colour);
      styles.push_back(1);
    }
    legend(pls, texts, opts, colours, styles, PL_POSITION_LEFT);
  });
}

}  // namespace iga
