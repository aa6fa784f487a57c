#pragma once
/// @file
/// Building T-mesh spaces from the `domain` and `space` config nodes.
///
///   domain: {type: rectangle, min: [x0, y0], max: [x1, y1]}
///   domain: {type: l_shape, min: [x0, y0], max: [x1, y1]}      # the box without its upper-right quarter
///   space:  {type: tmesh, section: poly|trig|hyperbolic, n: 3, regularity: 1, frequency: 1,
///            elements: [nx, ny], refine: [[x0, y0, x1, y1], ...],
///            refine_near: [{point: [x, y], times: k}, {box: ...}, {curve: ...}],
///            sections_in: [{box: [[x0, y0], [x1, y1]], section: trig, frequency: 1}]}
///
/// `section` and `frequency` may be [x, y] pairs; `sections_in` gives base cells other section
/// spaces (sections_from_config.hpp).
///
/// `refine` boxes are in coordinates relative to the domain's box ([0,1]^2); each, in order, splits
/// every cell inside it into four. Then `refine_near` (refine_near_from_config.hpp, physical
/// coordinates) refines the cells meeting each target. `level` then splits every cell `level` times. Defaults:
/// regularity (n-1)/2 (the largest r with n >= 2r+1), frequency 1, elements [2, 2].
/// Every error is an InputError naming the config place (exit code 2).

#include "config/config_node.hpp"
#include "spaces/space.hpp"

namespace iga {

SpacePtr make_tmesh_space(const ConfigNode& domain, const ConfigNode& space, int level);

}  // namespace iga
