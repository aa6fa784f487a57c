#pragma once
/// @file
/// A study with its files: every level's solution_<l>.vtu / mesh_<l>.vtu (and surface_<l>.vtu, the
/// surface with its normals, for spaces on surfaces in 3D) and the .pvd collections,
/// written as the study goes (the study loop itself writes nothing).

#include <string>

#include "solver/study.hpp"

namespace iga {

/// Run the study of `settings`, writing the VTK outputs it asks for into `directory` (which exists).
StudyResult run_study_with_vtk(const StudySettings& settings, const std::string& directory,
                               const ProgressSink& progress);

}  // namespace iga
