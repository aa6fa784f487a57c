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
/// `coarser`, when given, is a space built from the same two nodes at a lower level: the new space
/// may share its expensive level-independent parts (the smooth surface of a surface space) instead
/// of building them again; the caller owns it, the new space keeps what it shares alive.
/// Throws InputError naming the config place for anything it cannot build.
SpacePtr make_space(const ConfigNode& domain, const ConfigNode& space, int level, const Space* coarser = nullptr);

}  // namespace iga
