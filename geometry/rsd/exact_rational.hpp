#pragma once
/// @file
/// Exact rationals (GiNaC numbers) as the coefficient field of Poly, for the paper's GCD method
/// whose zero tests are meaningless in floating point (note §3.6).

#include <ginac/ginac.h>

#include "geometry/rsd/univariate_polynomial.hpp"

namespace iga::rsd {

template <>
struct Field<GiNaC::numeric> {
  static bool is_zero(const GiNaC::numeric& x) { return x.is_zero(); }
};

}  // namespace iga::rsd
