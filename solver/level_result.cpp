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

std::optional<double> least_squares_rate(const std::vector<double>& h, const std::vector<std::optional<double>>& e) {
  if (h.size() != e.size())
    throw std::invalid_argument("least_squares_rate: " + std::to_string(h.size()) + " mesh sizes but " +
                                std::to_string(e.size()) + " errors");
  std::vector<double> lx, ly;
  for (std::size_t i = 0; i < h.size(); ++i)
    if (e[i] && loggable(*e[i], h[i])) {
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

}  // namespace iga
