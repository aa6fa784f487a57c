#pragma once
/// @file
/// The files of a geometry study (geometry/geometry_study.hpp): geometry.csv (one row per level
/// with errors and rates), summary.json (the same, each level's surface report, the files), and
/// per level surface_<l>.vtu and surface_<l>_patches.txt (output/surface_files.hpp) up to
/// study.surface_files_up_to_level.

#include <string>
#include <vector>

#include "geometry/geometry_study.hpp"

namespace iga {

/// Runs the study, writing each level's surface files into `directory` (which exists) as it goes,
/// then geometry.csv and summary.json.
std::vector<GeometryLevel> run_geometry_study_with_files(const GeometryStudySettings& settings,
                                                         const std::string& directory,
                                                         const std::function<void(const std::string&)>& progress);

/// The table printed at the end: level, triangles, h, each error with its rate, max G1 residual.
std::string format_geometry_table(const std::vector<GeometryLevel>& rows);

}  // namespace iga
