#pragma once
/// @file
/// The `limits:` section of a config: how large a study may get before anything is allocated.
/// Every limit message names its key (limits.max_dofs, ...) so a user who means it can raise it.
/// Plain data, in the lowest layer, so that any layer (the mesh generator, the spaces, the study
/// loop) can be handed the numbers it needs.

#include <optional>
#include <string>

#include "config/config_node.hpp"

namespace iga {

struct ResourceLimits {
  int max_degree = 12;               ///< limits.max_degree: polynomial degree of a space
  double max_elements = 4e6;         ///< limits.max_elements: elements of one level (and of a generated mesh)
  double max_dofs = 5e6;             ///< limits.max_dofs: degrees of freedom of one level
  double max_memory_gb = 0.0;        ///< limits.max_memory_gb: estimated memory of one level (GB = 1e9 bytes)
  std::string where = "limits";      ///< config place of the section, for messages
};

/// 3/4 of this machine's physical memory in GB (16 GB when it cannot be read): the default of
/// limits.max_memory_gb.
double default_memory_gb();

/// Defaults (max_memory_gb = default_memory_gb()) overridden by the keys of `section` (the
/// config's `limits:` map, if any). Each key must be a positive number.
ResourceLimits parse_limits(const std::optional<ConfigNode>& section);

/// " (raise limits.KEY in the config if this is intended)": the tail of every limit message.
std::string how_to_raise(const std::string& key);

}  // namespace iga
