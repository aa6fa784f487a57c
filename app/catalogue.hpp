#pragma once
/// @file
/// What `iga-run --list` prints: every space type with a line on its functions, and under it the
/// domain types it is built on with their keys and built-in layouts. Generated from the spaces' own
/// entries (space_catalogue in spaces/space_factory.hpp), so it lists what the builders accept.

#include <string>

namespace iga {

/// The listing, ready to print.
std::string catalogue_text();

}  // namespace iga
