#pragma once
/// @file
/// Seeded random perturbation of the interior vertices of a WS4 triangulation (meshes that are not
/// translation-invariant, to check that rates do not rely on a uniform grid).

#include "spaces/ws4/triangulation.hpp"

namespace iga::ws4 {

/// Move every vertex not on a boundary edge by a uniform random offset in [-a, a]² with
/// a = fraction * (shortest edge at that vertex). Deterministic for a given seed.
/// @param fraction in [0, 0.25) so that no triangle flips (checked by the caller).
void jitter_interior_vertices(Triangulation& mesh, double fraction, unsigned seed);

}  // namespace iga::ws4
