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

#include <functional>
#include <vector>

#include "spaces/g1_4split/gluing.hpp"
#include "spaces/g1_4split/quad_topology.hpp"

namespace iga {

struct LineGluingReport {
  int lines = 0;          ///< mesh lines (open and closed)
  int zigzag_lines = 0;   ///< lines turned to zigzag data to resolve a conflict
  bool mesh_fans = false; ///< vertexwise_gluing from the mesh's own fans (then `lines` counts its chains)
};

/// The gluing value a vertex gives one of its edges (outward: a(γ) seen from the vertex).
using EndValue = std::function<double(int vertex, int edge)>;

/// Gluing per edge (unused entries for boundary edges) from the vertex values (used at the ends
/// of the lines only): `end_value(v, e)`, or the same A for every edge of a vertex.
std::vector<SplitGluing> line_gluing(const QuadTopology& t, const EndValue& end_value,
                                     LineGluingReport* report = nullptr);
std::vector<SplitGluing> line_gluing(const QuadTopology& t, const std::vector<double>& vertex_value,
                                     LineGluingReport* report = nullptr);

/// Gluing linear on each edge between end values given at every vertex (e.g. from the mesh's own
/// fans, fan_values.hpp), where these already satisfy Condition 1 at every vertex. At interior
/// vertices where all four values vanish (true crossings) the twist condition needs equal slopes on
/// opposite edges: along each chain of edges through such vertices the mid-edge values alternate
/// ±μ (μ fitted to the linear mids, kept away from 0 where the chain has a kink). Empty when that
/// fails (a chain that closes with an odd sign, a kink with a(½) = 0).
std::vector<SplitGluing> vertexwise_gluing(const QuadTopology& t, const EndValue& end_value,
                                           LineGluingReport* report = nullptr);

/// The edge opposite to `edge` at the interior valence-4 vertex v (the one sharing no face corner
/// with it there), or -1 when v is not an interior valence-4 vertex.
int opposite_edge(const QuadTopology& t, int v, int edge);

/// An interior vertex where every edge has a = 0 and two opposite edges have different outward
/// slopes a'(γ) (the twist condition fails there), or -1.
int twist_incompatible_vertex(const QuadTopology& t, const std::vector<SplitGluing>& gluing);

}  // namespace iga
