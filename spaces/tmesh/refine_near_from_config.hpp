#pragma once
/// @file
/// `space.refine_near` of a T-mesh config: cells meeting a point, a box or a parametric curve
/// (physical coordinates) refined a given number of times, each time admissibly (2:1 balance).
///
///   refine_near:
///     - {point: [0, 0], times: 3}
///     - {box: [[0, 0], [0.5, 0.5]], times: 1}
///     - {curve: {x: "0.5 + 0.3*cos(t)", y: "0.5 + 0.3*sin(t)", t: [0, 6.2832], samples: 512}, times: 2}
///
/// A point or curve refines the cells it meets (closed cells: a point at a vertex meets all cells
/// around it); a box the cells it overlaps with positive area. A curve is sampled at `samples` (default 512) equispaced parameters and treated as the polyline
/// through them; x and y are muParser expressions in t (constant pi; ^ for powers). `times`
/// defaults to 1. Each entry, in order, repeats `times` times: split every cell meeting the target,
/// plus what refine_admissibly adds. Errors (a target meeting no cell, a bad expression, the
/// lattice exhausted) are InputErrors naming the entry.

#include "config/config_node.hpp"
#include "spaces/tmesh/tmesh.hpp"

namespace iga {

/// `mesh` after the refinements listed by the `refine_near` node (a sequence).
TMesh refine_near_from_config(TMesh mesh, const ConfigNode& refine_near);

}  // namespace iga
