#pragma once
/// @file
/// The two kinds of failure iga-run reports, mapped to exit codes by the CLI:
/// InputError (bad config, mesh, unsupported parameter) exits 2; NumericalError (singular matrix,
/// failed factorization) exits 1. Messages are one line and name the place.

#include <stdexcept>
#include <string>

namespace iga {

struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct NumericalError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace iga
