#pragma once
/// @file
/// What `iga-run --list` prints: the space types, domain types and built-in meshes a config can
/// name, one line each.

#include <string>

namespace iga {

/// The listing, ready to print.
std::string catalogue_text();

}  // namespace iga
