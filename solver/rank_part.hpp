#pragma once
/// @file
/// What one rank of a distributed solve works on: its part of the space (spaces/space_part.hpp)
/// instead of the whole, so that its tables, vectors and solution grow with its share of the
/// elements. The part holds, in the whole's order, the rank's own elements (the Hilbert-curve
/// partition of petsc_partition.hpp) and the neighbours it only reads:
///  - every element with a boundary edge, so that the boundary projection of the essential
///    conditions (a boundary-sized problem, boundary_conditions.hpp) is the serial one on every
///    rank and the ranks agree on which functions are constrained;
///  - for spaces that report gradient jumps, the elements across the interior edges of its own
///    (the jump of an edge between two ranks is measured by both).
/// No PETSc types: every rank arrives at the same partition from the same space (the ranks of a run
/// compute it together in rank_part, each a block of the elements, petsc_session.hpp's collectives).

#include <memory>

#include "solver/formulation.hpp"
#include "spaces/space_part.hpp"

namespace iga {

/// The elements of `rank` of `ranks` (increasing): where a rank assembles on the whole space.
std::vector<int> rank_elements(const Space& space, int rank, int ranks);

/// The part of `whole` for `rank` of `ranks`. `whole` may be a skeleton (SpaceExtent::skeleton):
/// the part's space is then built on the part's elements only (on_elements, builds_on_elements.hpp), so that the
/// heavy per-element data of the mesh-based spaces is not replicated on every rank; its geometry,
/// numbering and edges (what the partition and the mesh outlines read) are the skeleton's.
std::shared_ptr<const SpacePart> rank_part(const std::shared_ptr<const Space>& whole, int rank, int ranks);

}  // namespace iga
