#pragma once
/// @file
/// The registry of spaces: the one place that knows every space type by its config name.

#include <string>
#include <vector>

#include "config/config_node.hpp"
#include "spaces/space.hpp"

namespace iga {

/// Config names of all spaces ("bspline", ...).
std::vector<std::string> space_types();

/// Build the space named by space["type"] on `domain`, uniformly refined `level` times.
/// Throws InputError naming the config place for anything it cannot build.
SpacePtr make_space(const ConfigNode& domain, const ConfigNode& space, int level);

}  // namespace iga
