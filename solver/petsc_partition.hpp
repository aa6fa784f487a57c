#pragma once
/// @file
/// How a distributed solve divides the work: elements to ranks along a space-filling curve through
/// their centres, and the unknowns of the reduced system to ranks (each to the lowest rank owning an
/// element it lives on), numbered so that every rank's unknowns are contiguous (PETSc's row layout).
/// Plain computation, no PETSc: every rank computes the same partition from the same space.

#include <vector>

#include "quadrature/quadrature_rule.hpp"

namespace iga {

/// Rank of each element: the elements sorted along a Hilbert curve through the bounding box of
/// their centres, cut into `parts` runs of equal length (±1). Neighbouring elements lie close on
/// the curve, so each run is a compact piece of the domain.
std::vector<int> partition_elements(const std::vector<Point2>& centres, int parts);

/// Position of (x, y) along the Hilbert curve filling the 2^order × 2^order grid.
unsigned long long hilbert_index(unsigned x, unsigned y, int order);

/// The unknowns of a system whose element e couples the unknowns unknowns_of(e) (CSR: offsets,
/// indices), distributed over ranks.
struct UnknownLayout {
  std::vector<int> owner;      ///< rank of each unknown
  std::vector<int> global;     ///< unknown -> its row in the distributed numbering
  std::vector<int> first_row;  ///< rank r owns rows first_row[r] .. first_row[r+1]
};

/// Each unknown goes to the lowest rank among the owners of the elements it lives on (an unknown on
/// no element, which cannot happen in an assembled system, goes to rank 0).
UnknownLayout layout_unknowns(const std::vector<int>& element_offsets, const std::vector<int>& element_unknowns,
                              const std::vector<int>& element_owner, int num_unknowns, int parts);

/// Nonzeros of the rows a rank owns, for preallocating its part of the distributed matrix: row r
/// couples the unknowns of every element r lives on.
struct RowCouplings {
  std::vector<int> on_rank_columns;   ///< per owned row: columns owned by the same rank
  std::vector<int> off_rank_columns;  ///< per owned row: columns owned by other ranks
  long long off_rank = 0;             ///< Σ off_rank_columns (couplings that cross ranks)
  long long total = 0;                ///< Σ of both
};

/// The couplings of `rank`'s rows (element -> unknowns in CSR as for layout_unknowns).
RowCouplings row_couplings(const std::vector<int>& element_offsets, const std::vector<int>& element_unknowns,
                           const UnknownLayout& layout, int rank);

}  // namespace iga
