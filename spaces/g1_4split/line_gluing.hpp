#pragma once
/// @file
/// Gluing data for the 4-split G1 space that are optimal on every quad mesh (blending `lines`).
///
/// Why: on a sub-edge of a nested refinement a(t) must be linear, else a·p' ∈ U¹_k caps the degree
/// of the traces along the coarse edges (half an order lost, the q1 blending). Linear data per edge
/// have a slope a'(γ) ≠ 0, and at an interior crossing vertex (all four a = 0) the twists close
/// only if opposite edges have equal outward slopes (Condition 2 of the note).
///
/// What: a mesh line is a maximal chain of interior edges that goes straight through every interior
/// valence-4 vertex (to the opposite edge); it ends at the other vertices or closes. Along a line
/// a is linear in the edge count, from A(v₀) at its first end to −A(v_L) at its last (A = the
/// vertex's symmetric gluing value; a closed line has a ≡ 0). Then the slope is the same on both
/// sides of every vertex inside the line, so the twist condition holds wherever the vertex is
/// crossing, and a vertex where one line is non-zero has values (α, 0, −α, 0): Condition 1 holds
/// (it is the vertex a nested split creates in the middle of an edge). Two lines non-zero at one
/// valence-4 vertex would break Condition 1; one of them then becomes a "zigzag" line: value 0 at
/// every vertex inside it, linear on each half edge with mid-edge values ±μ alternating (slopes
/// ∓2μ equal on both sides of each vertex, a(½) = ±μ ≠ 0 so the kink at ½ forces nothing on p'(½)).
/// Every piece is linear, so refined sub-edges carry linear data: nested, separable, optimal.

#include <vector>

#include "spaces/g1_4split/gluing.hpp"
#include "spaces/g1_4split/quad_topology.hpp"

namespace iga {

struct LineGluingReport {
  int lines = 0;          ///< mesh lines (open and closed)
  int zigzag_lines = 0;   ///< lines turned to zigzag data to resolve a conflict
};

/// Gluing per edge (unused entries for boundary edges) from the symmetric vertex values
/// `vertex_value` (A of every vertex; used at the ends of the lines only).
std::vector<SplitGluing> line_gluing(const QuadTopology& t, const std::vector<double>& vertex_value,
                                     LineGluingReport* report = nullptr);

/// The edge opposite to `edge` at the interior valence-4 vertex v (the one sharing no face corner
/// with it there), or -1 when v is not an interior valence-4 vertex.
int opposite_edge(const QuadTopology& t, int v, int edge);

/// An interior vertex where every edge has a = 0 and two opposite edges have different outward
/// slopes a'(γ) (the twist condition fails there), or -1.
int twist_incompatible_vertex(const QuadTopology& t, const std::vector<SplitGluing>& gluing);

}  // namespace iga
