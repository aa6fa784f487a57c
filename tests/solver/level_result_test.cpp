/// @file
/// Convergence rates from synthetic error sequences with known exponents.

#include "solver/level_result.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace iga {
namespace {

TEST(LevelResultRate, PairOfLevelsWithPowerLawErrorGivesExponent) {
  const double C = 7.3;
  for (double h : {0.5, 0.1, 1e-3}) {
    const double h_fine = h / 2.7;  // rates must not depend on a refinement factor of 2
    const auto r = rate(C * std::pow(h, 3), C * std::pow(h_fine, 3), h, h_fine);
    ASSERT_TRUE(r.has_value());
    EXPECT_NEAR(*r, 3.0, 1e-12) << "h = " << h;
  }
}

TEST(LevelResultRate, MissingOrDegenerateDataGivesNoRate) {
  EXPECT_FALSE(rate(std::nullopt, 1e-3, 0.5, 0.25).has_value());
  EXPECT_FALSE(rate(1e-2, std::nullopt, 0.5, 0.25).has_value());
  EXPECT_FALSE(rate(1e-2, 0.0, 0.5, 0.25).has_value());   // exact reproduction: no logarithm
  EXPECT_FALSE(rate(1e-2, 1e-3, 0.5, 0.5).has_value());   // same mesh twice
}

TEST(LevelResultLeastSquares, PowerLawGivesExponent) {
  std::vector<double> h;
  std::vector<std::optional<double>> e;
  for (int k = 0; k < 6; ++k) {
    h.push_back(std::pow(0.5, k));
    e.push_back(0.25 * std::pow(h.back(), 3));
  }
  const auto r = least_squares_rate(h, e);
  ASSERT_TRUE(r.has_value());
  EXPECT_NEAR(*r, 3.0, 1e-12);
}

TEST(LevelResultLeastSquares, SkipsRowsWithoutError) {
  const std::vector<double> h = {1.0, 0.5, 0.25, 0.125, 0.0625};
  std::vector<std::optional<double>> e;
  for (double hk : h) e.push_back(2.0 * hk * hk * hk);
  e[0] = std::nullopt;
  e[2] = std::nullopt;
  const auto r = least_squares_rate(h, e);
  ASSERT_TRUE(r.has_value());
  EXPECT_NEAR(*r, 3.0, 1e-12);
}

TEST(LevelResultLeastSquares, FitsAllPointsNotJustTheEnds) {
  // log2 e = -3 k + d_k with d = (+0.3, -0.6, +0.3): d has zero mean and is orthogonal to the
  // centred abscissae (-1, 0, 1), so the least-squares slope is exactly 3 while neither
  // consecutive pair has rate 3.
  const std::vector<double> h = {1.0, 0.5, 0.25};
  const double d[3] = {0.3, -0.6, 0.3};
  std::vector<std::optional<double>> e;
  for (int k = 0; k < 3; ++k) e.push_back(std::pow(2.0, -3.0 * k + d[k]));
  const auto r = least_squares_rate(h, e);
  ASSERT_TRUE(r.has_value());
  EXPECT_NEAR(*r, 3.0, 1e-12);
  EXPECT_NEAR(*rate(e[0], e[1], h[0], h[1]), 3.9, 1e-12);
  EXPECT_NEAR(*rate(e[1], e[2], h[1], h[2]), 2.1, 1e-12);
}

TEST(LevelResultLeastSquares, FewerThanTwoPointsGivesNoRate) {
  EXPECT_FALSE(least_squares_rate({}, {}).has_value());
  EXPECT_FALSE(least_squares_rate({0.5}, {1e-2}).has_value());
  EXPECT_FALSE(least_squares_rate({0.5, 0.25, 0.125}, {std::nullopt, 1e-3, std::nullopt}).has_value());
  EXPECT_FALSE(least_squares_rate({0.5, 0.5}, {1e-2, 1e-3}).has_value());  // no spread in h
}

TEST(LevelResultLeastSquares, MismatchedLengthsThrow) {
  EXPECT_THROW(least_squares_rate({0.5, 0.25}, {1e-2}), std::invalid_argument);
}

}  // namespace
}  // namespace iga
