// Double-double arithmetic: the error-free transformations are exact and the operations keep
// about 32 digits where double keeps 16 (checked against long double and exact identities).
#include <gtest/gtest.h>

#include <cmath>

#include "config/double_double.hpp"

using namespace iga;

TEST(DoubleDouble, TwoProductIsExact) {
  // (1 + 2^-30)^2 = 1 + 2^-29 + 2^-60: the last term is below double's resolution of 1.
  const double a = 1.0 + std::ldexp(1.0, -30);
  const DoubleDouble p = dd_detail::two_prod(a, a);
  EXPECT_EQ(p.hi, 1.0 + std::ldexp(1.0, -29));
  EXPECT_EQ(p.lo, std::ldexp(1.0, -60));
}

TEST(DoubleDouble, SumKeepsWhatDoubleLosesUnderCancellation) {
  // (1e16 + 1) − 1e16 is 0 in double, 1 in double-double.
  const DoubleDouble big = DoubleDouble(1e16) + DoubleDouble(1.0);
  const DoubleDouble d = big - DoubleDouble(1e16);
  EXPECT_EQ(d.hi, 1.0);
  EXPECT_EQ(d.lo, 0.0);
}

TEST(DoubleDouble, DivisionAndSquareRootReachTwiceDoublePrecision) {
  // 1/3 · 3 − 1 and sqrt(2)² − 2 vanish to ≈ 1e-32, far below double's 1e-16.
  const DoubleDouble third = DoubleDouble(1.0) / DoubleDouble(3.0);
  const DoubleDouble r = third * 3.0 - DoubleDouble(1.0);
  EXPECT_LT(std::abs(r.hi), 1e-31);
  const DoubleDouble s = sqrt(DoubleDouble(2.0));
  const DoubleDouble t = s * s - DoubleDouble(2.0);
  EXPECT_LT(std::abs(t.hi), 1e-31);
  // The high part is the double result.
  EXPECT_EQ(third.hi, 1.0 / 3.0);
  EXPECT_EQ(s.hi, std::sqrt(2.0));
}

TEST(DoubleDouble, LongDoubleRoundTripIsExact) {
  const long double x = 1.0L / 3.0L;
  EXPECT_EQ(DoubleDouble::from_long_double(x).to_long_double(), x);
}
