#include "solver/level_result.hpp"

#include <cmath>
#include <stdexcept>

namespace iga {

namespace {

/// Both logarithms below are defined (a zero error, e.g. an exactly reproduced solution, has no rate).
bool loggable(double e, double h) { return e > 0 && h > 0 && std::isfinite(e) && std::isfinite(h); }

}  // namespace

std::optional<double> rate(std::optional<double> e_prev, std::optional<double> e, double h_prev, double h) {
  if (!e_prev || !e || !loggable(*e_prev, h_prev) || !loggable(*e, h) || h_prev == h) return std::nullopt;
  return std::log(*e_prev / *e) / std::log(h_prev / h);
}

std::optional<double> least_squares_rate(const std::vector<double>& h, const std::vector<std::optional<double>>& e,
                                         const std::vector<bool>& skip) {
  if (h.size() != e.size())
    throw std::invalid_argument("least_squares_rate: " + std::to_string(h.size()) + " mesh sizes but " +
                                std::to_string(e.size()) + " errors");
  std::vector<double> lx, ly;
  for (std::size_t i = 0; i < h.size(); ++i)
    if (e[i] && loggable(*e[i], h[i]) && !(i < skip.size() && skip[i])) {
      lx.push_back(std::log(h[i]));
      ly.push_back(std::log(*e[i]));
    }
  const auto n = static_cast<double>(lx.size());
  if (lx.size() < 2) return std::nullopt;
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < lx.size(); ++i) mx += lx[i], my += ly[i];
  mx /= n;
  my /= n;
  // Centred sums keep the slope accurate when log h values are large and close together.
  double sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < lx.size(); ++i) {
    sxx += (lx[i] - mx) * (lx[i] - mx);
    sxy += (lx[i] - mx) * (ly[i] - my);
  }
  if (sxx == 0) return std::nullopt;  // all rows on the same mesh size
  return sxy / sxx;
}

std::vector<bool> round_off_floor(const std::vector<double>& x, const std::vector<std::optional<double>>& e) {
  std::vector<bool> floor(e.size(), false);
  if (x.size() != e.size() || e.empty() || !e[0]) return floor;
  for (std::size_t i = 2; i < e.size(); ++i) {
    const auto before = rate(e[i - 2], e[i - 1], x[i - 2], x[i - 1]);
    const auto now = rate(e[i - 1], e[i], x[i - 1], x[i]);
    const bool clean_before = before && *before >= 1.0;
    const bool stalled = now && *now < 0.5 * *before && *now < 1.0;
    const bool tiny = e[i - 1] && *e[i - 1] <= 1e-4 * *e[0];
    if (clean_before && stalled && tiny) {
      for (std::size_t j = i; j < e.size(); ++j) floor[j] = true;
      break;
    }
  }
  return floor;
}

}  // namespace iga
