#pragma once
/// @file
/// `domain: {type: surface, ...}` (geometry/surface_from_config.hpp) with `space: {type: surface,
/// degree: p}`: C0 Bernstein elements of degree p on 2^level × 2^level sub-triangles of every
/// patch of the G1 surface.

#include "config/config_node.hpp"
#include "spaces/space.hpp"

namespace iga {

SpacePtr make_surface_space(const ConfigNode& domain, const ConfigNode& space, int level);

}  // namespace iga
