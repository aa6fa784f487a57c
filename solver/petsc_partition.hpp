#pragma once
/// @file
/// How a distributed solve divides the work: elements to ranks along a space-filling curve through
/// their centres (the unknowns follow, petsc_distribution.hpp). Plain computation, no PETSc: every
/// rank computes the same partition from the same space.

#include <vector>

#include "quadrature/quadrature_rule.hpp"

namespace iga {

/// Rank of each element: the elements sorted along a Hilbert curve through the bounding box of
/// their centres, cut into `parts` runs of equal length (±1). Neighbouring elements lie close on
/// the curve, so each run is a compact piece of the domain.
std::vector<int> partition_elements(const std::vector<Point2>& centres, int parts);

/// The steps of partition_elements, for ranks that each compute the keys of some elements: the
/// position of each centre along the Hilbert curve through the square box on [lo, hi] (the bounding
/// box of all centres), and the rank of each element from all keys (sorted by key, then element
/// number, and cut into `parts` runs of equal length, ±1; the cuts are found by selection, not by
/// sorting every key).
std::vector<unsigned long long> hilbert_keys(const std::vector<Point2>& centres, const Point2& lo, const Point2& hi);
std::vector<int> partition_by_keys(const std::vector<unsigned long long>& keys, int parts);

/// Position of (x, y) along the Hilbert curve filling the 2^order × 2^order grid.
unsigned long long hilbert_index(unsigned x, unsigned y, int order);

}  // namespace iga
