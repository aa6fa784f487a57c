#pragma once
/// @file
/// Named boundary parts of a multipatch PatchMesh: its boundary groups when it has any (e.g. the
/// physical curves of a Gmsh file), otherwise the sides of the domain's bounding box. A boundary
/// edge whose two ends lie on x = x_min (within 1e-10 of the domain size) belongs to `left`, on
/// x = x_max to `right`, on y = y_min to `bottom`, on y = y_max to `top`. Edges on no side of the
/// box (e.g. the re-entrant sides of an L-shape, the slanted sides of a pentagon) are only in "all".

#include <string>
#include <vector>

#include "spaces/g1/patch_mesh.hpp"
#include "spaces/space.hpp"

namespace iga {

/// The parts into the facts of a space on `mesh`: "all" (every boundary edge), then the group
/// names (in order), or the nonempty sides among left, right, bottom, top, in that order.
void set_boundary_parts(const PatchMesh& mesh, SpaceFacts& facts);

}  // namespace iga
