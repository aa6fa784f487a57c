#pragma once
/// @file
/// Building a WS4 space from the `domain` and `space` config nodes:
///
///   domain: {type: unit_square}
///   domain: {type: rectangle, min: [x0, y0], max: [x1, y1]}
///   domain: {type: unit_square, jitter: 0.15, seed: 3}   # either type; perturbed mesh
///   space:  {type: ws4, elements: N}          # or [nx, ny]; default 2
///
/// The mesh is the nx x ny grid of squares, each split by a diagonal alternating in a checkerboard
/// (WS4 notes §10); refinement level l splits every triangle into 4, l times. With `jitter` (in
/// [0, 0.2]), the interior vertices of each level are then moved at random by up to jitter x the
/// shortest edge at the vertex (ws4_jitter.hpp; seed + level seeds the generator, default seed 1).
/// Every error is an InputError naming the config place (exit code 2).

#include "solver/config_node.hpp"
#include "spaces/space.hpp"

namespace iga {

SpacePtr make_ws4_space(const ConfigNode& domain, const ConfigNode& space, int level);

}  // namespace iga
