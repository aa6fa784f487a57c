#pragma once
/// @file
/// One unit normal field on a surface space: a sign per element such that sign_e (x_ξ × x_η) is
/// continuous across every interior edge, with its global sign chosen "outward". Elements of a
/// surface need not agree on their parametrisation's orientation (a quad mesh file's faces are not
/// required to be consistently ordered), so a load along the normal (a shell's pressure) needs this.
///
/// Outward, per connected piece of the surface: the sign that makes V = ∫ (x − x₀)·n dA positive
/// (x₀ the piece's centroid). On a closed surface V is three times the enclosed volume whatever x₀,
/// so n points out of the enclosed solid; on an open curved shell (a roof, a hemisphere, a cap) it
/// points to its convex side, away from its centroid. Where |V| ≤ 1e-6 A L (flat or
/// evenly saddle-shaped pieces; A the area, L the largest distance from x₀), the mean normal ∫ n dA
/// decides: its largest component is made positive (a plate in the plane z = 0: n = +z).

#include <vector>

#include "spaces/space.hpp"

namespace iga {

struct SurfaceOrientation {
  /// +1 or −1 per element: the oriented normal on element e is sign[e] · x_ξ × x_η / |x_ξ × x_η|.
  std::vector<int> sign;
  /// False when some cycle of elements flips the normal (a non-orientable surface: no normal field).
  bool orientable = true;
  /// False when a piece is neither curved enough nor has a mean normal (|V| and |∫ n| both at
  /// rounding level): the outward choice is then arbitrary (element 0's parametrisation).
  bool decided = true;
  /// True when some piece was oriented by its mean normal (flat), not by V.
  bool flat = false;
  /// Number of connected pieces, and Σ V/3 over them after orienting (the enclosed volume of a
  /// closed surface), for notes and tests.
  int pieces = 0;
  double volume = 0.0;
};

/// Orient the normal of `space` (ambient_dimension() == 3, interior_edges() listed).
SurfaceOrientation orient_surface(const Space& space, int quad_degree);

}  // namespace iga
