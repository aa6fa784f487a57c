#pragma once
/// @file
/// Section spaces of a T-mesh config: one family (and frequency) everywhere, one per direction,
/// or other ones on the base cells of given regions.
///
///   section: trig | [trig, poly]          # the family in x and in y (default poly)
///   frequency: 1 | [1, 2]                 # w in x and in y (default 1; ignored by poly)
///   sections_in:                          # base cells overlapping a box get other sections
///     - {box: [[0, 0], [1.5, 1.5]], section: poly, frequency: 1}
///
/// Regions apply in order to the base cells (before any refinement, so refined cells inherit them
/// and the levels stay nested); a later region overrides an earlier one. Edges between cells of
/// different section spaces have d_e = 0, which the Hermite basis supports for n >= 2r+3.

#include <array>

#include "config/config_node.hpp"
#include "spaces/tmesh/tmesh.hpp"

namespace iga {

/// `mesh` (a base mesh, every cell on section 0) with the sections of `space` (its `section`,
/// `frequency` and `sections_in` keys) assigned to its cells.
TMesh with_sections_from_config(const TMesh& mesh, const ConfigNode& space, int n);

/// InputError (at `space.frequency`, else `space`) unless w h < pi on every trigonometric cell
/// side (the normalized B-basis degenerates at w h = pi).
void check_trigonometric_cells(const TMesh& mesh, const ConfigNode& space);

}  // namespace iga
