#pragma once
/// @file
/// Sample cells that follow the WS4 split, so that a drawing interpolates linearly only inside the
/// polynomial pieces of a macro-element.

#include "spaces/space.hpp"

namespace iga::ws4 {

/// resolution < 16: the 178 split vertices and the 342 fan triangles over them (shared points).
/// resolution >= 16: every fan triangle subdivided uniformly into m² triangles, m = resolution / 8
/// (points of different fan triangles are not shared).
SampleCell split_sample_cell(int resolution);

}  // namespace iga::ws4
