#pragma once
/// @file
/// The knot multisets and weights of the 51 WS4 simplex splines (Lyche–Manni–Speleers 2024,
/// Fig. 5, as reconstructed and verified in the WS4 notes §5).

#include <array>

namespace iga::ws4 {

/// Knot multiset of B_{i+1}: multiplicity of each of the 12 boundary points (order of
/// Ws4Split::boundary_points), 7 knots in all; and c_i with weight w_i = c_i |Δ| / 480.
struct KnotSet {
  std::array<int, 12> multiplicity;
  int c;
};

/// The 51 knot sets, index i for B_{i+1}.
const std::array<KnotSet, 51>& ws4_knot_sets();

}  // namespace iga::ws4
