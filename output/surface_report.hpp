#pragma once
/// @file
/// The report of a smooth surface as the `surface` object of summary.json: its labels as strings,
/// its measures as numbers (integers where they are counts or degrees), plus `patches`.

#include <nlohmann/json.hpp>

#include "geometry/surface_patches.hpp"

namespace iga {

nlohmann::json surface_report_json(const SurfacePatches& surface);

}  // namespace iga
