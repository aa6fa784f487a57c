#pragma once
/// @file
/// The C0 and G1 equations of the 4-split space on the broken coefficient vector (face f's
/// coefficient b_{i,j} at f (m+1)² + i + j (m+1)), edge by edge, and the index sets the local
/// construction splits them into: per face corner a 2x2 corner block, per face side a strip (rows 0
/// and 1 next to the edge, positions 2..m-2), the interior (positions 2..m-2 in both directions).

#include <Eigen/Core>
#include <vector>

#include "spaces/g1_4split/gluing.hpp"
#include "spaces/g1_4split/quad_topology.hpp"
#include "spaces/g1_4split/split_bspline.hpp"

namespace iga {

/// Local indices of row `row` (0 on the edge, 1 next to it) along local edge j of a face, in the
/// edge's own direction (corner j to corner j+1): m + 1 entries.
std::vector<int> side_row(const SplitBSpline& b, int local_edge, int row);

/// The 4 local indices of the 2x2 block at corner c.
std::vector<int> corner_block(const SplitBSpline& b, int corner);

/// Local indices at distance >= 2 from every edge ((m-3)² face functions).
std::vector<int> interior_indices(const SplitBSpline& b);

/// The rows 0 and 1 of every side of edge e in the edge's t direction (g0 -> g1), as global broken
/// indices: rows[s][0] and rows[s][1] for side s, m + 1 entries each.
std::vector<std::array<std::vector<int>, 2>> split_edge_rows(const QuadTopology& t, const SplitBSpline& b, int e);

/// All C0 and G1 equations of interior edge e, exactly (the G1 residual is a polynomial of degree
/// <= k + 2 per half, collocated at k + 4 points per half): a dense matrix over `columns`, the
/// global indices of rows 0 and 1 of both sides (4(m+1) entries, side 0 row 0, side 0 row 1,
/// side 1 row 0, side 1 row 1, each in t order).
Eigen::MatrixXd edge_equations(const QuadTopology& t, const SplitBSpline& b, const SplitGluing& a, int e,
                               std::vector<int>& columns);

/// The equations edge e imposes on the corner data at its end `end` (0: g0, 1: g1), i.e. on the
/// corner blocks of its two faces there: value and tangential derivative agree, the G1 relation at
/// the vertex, and, when a vanishes there (a crossing end), its derivative along the edge (twists).
/// Dense over `columns` (the 8 global indices of the two corner blocks).
Eigen::MatrixXd vertex_equations(const QuadTopology& t, const SplitBSpline& b, const SplitGluing& a, int e, int end,
                                 std::vector<int>& columns);

}  // namespace iga
