#pragma once
/// @file
/// `domain: {type: surface, ...}` (geometry/surface_from_config.hpp) with `space: {type: surface,
/// degree: p}`: C0 Bernstein elements of degree p on 2^level × 2^level sub-triangles of every
/// patch of the G1 surface. The surface is built from `domain`, or shared with `coarser` when that
/// is a surface space (the study passes the previous level: one surface for all levels, owned by
/// the spaces that use it).

#include "config/config_node.hpp"
#include "spaces/space.hpp"

namespace iga {

SpacePtr make_surface_space(const ConfigNode& domain, const ConfigNode& space, int level,
                            const Space* coarser = nullptr);

}  // namespace iga
