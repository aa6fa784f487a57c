#pragma once
/// @file
/// Local dyadic refinement of a T-mesh that keeps it admissible (regular, no cycle of T-junctions),
/// as adaptive refinement needs (notes §4, §7.4).

#include <stdexcept>
#include <string>
#include <vector>

#include "spaces/tmesh/tmesh.hpp"

namespace iga {

/// Split the `marked` cells into four, and also every cell needed so that
///  1. neighbours across a side differ at most by a factor 2 in size (2:1 balance, iterated to a
///     fixed point), and
///  2. the result is regular and acyclic: if it is not, the side neighbours of every split cell are
///     split as well (a one-cell buffer) and the balance closure is repeated, a few times at most.
/// Throws std::runtime_error when a cell to split is one lattice unit (2^-24 of the initial cells) or when no admissible mesh is reached. Marked indices out of range throw
/// std::out_of_range; an empty `marked` returns a copy of the mesh.
TMesh refine_admissibly(const TMesh& mesh, const std::vector<int>& marked);

/// Pairs (a, b), a < b, of cells sharing a piece of side of positive length.
std::vector<std::pair<int, int>> side_neighbours(const TMesh& mesh);

}  // namespace iga
