#pragma once
/// @file
/// Building G1 multipatch spaces from config:
///   domain: {type: multipatch, name: 3p_square | 5p_square | pentagon}
///   space:  {type: g1, degree: k}
/// Errors are InputErrors naming the config place (exit code 2).

#include "solver/config_node.hpp"
#include "spaces/space.hpp"

namespace iga {

/// The G1 space of degree k on the named multipatch domain, every patch split uniformly into
/// 4^level bilinear sub-patches (the geometry unchanged).
SpacePtr make_g1_space(const ConfigNode& domain, const ConfigNode& space, int level);

}  // namespace iga
