#pragma once
/// @file
/// Building B-spline spaces and patch geometries from the `domain` and `space` config nodes.
///
///   domain: {type: rectangle, min: [x0, y0], max: [x1, y1]}
///   domain: {type: quarter_annulus, inner: r0, outer: r1}
///   domain: {type: patch, degree: [pu, pv], knots_u: [...], knots_v: [...],
///            control_points: [[x, y], ...], weights: [...]}          # weights optional (NURBS)
///   space:  {type: bspline, degree: p, regularity: r, elements: [nx, ny]}
///
/// Every error is an InputError naming the config place (exit code 2).

#include <memory>
#include <vector>

#include "config/config_node.hpp"
#include "spaces/bspline/patch_geometry.hpp"
#include "spaces/space.hpp"
#include "spaces/space_request_size.hpp"

namespace iga {

/// The `regularity` key of `space` for degree p: 0..p-1, default p-1 (InputError at the key).
int read_regularity(const ConfigNode& space, int p);

/// B-spline space of degree p, regularity r (0..p-1, default p-1) and `elements` (default [2,2],
/// counted over the whole patch) refined uniformly `level` times: elements x 2^level per
/// direction, the geometry unchanged. For a patch domain each direction's element count must be
/// a multiple of the geometry's spans, which are subdivided uniformly (so the space's breakpoints
/// contain the geometry's).
SpacePtr make_bspline_space(const ConfigNode& domain, const ConfigNode& space, int level);

/// Levels 0 .. levels-1 of a B-spline space from its request alone (empty when the request is not
/// one the builder would take: it says why): [nx, ny] elements of degree p and regularity r
/// (defaults [2, 2], r = p - 1) halved `level` times give nx ny 4^level elements,
/// prod_d (n_d 2^level (p - r) + r + 1) DOFs (open knot vectors; a domain patch's own interior knots
/// add a few) and (p + 1)^4 entries per element.
std::vector<SpaceRequestSize> bspline_requested_sizes(const ConfigNode& space, int levels);

}  // namespace iga
