#pragma once
/// @file
/// `output.matrices: true`: each level's linear system in Matrix Market files, so that other
/// solvers can be tried on it. Into `<directory>/matrices/`, per level l:
///   matrix_<l>.mtx     A_free: the system on the free functions (coordinate, real, general)
///   rhs_<l>.mtx        b_free: its right-hand side (boundary data already moved over)
///   solution_<l>.mtx   u_free: what iga-run solved (array, real)
///   free_dofs_<l>.txt  row i of the system is global basis function free_dofs[i] (one per line)
/// The system is assembled again for the files (the solve itself keeps no copy of it).

#include <string>

#include "solver/study.hpp"

namespace iga {

/// A LevelSink writing the files above into `directory`/matrices (created on the first level).
LevelSink matrix_market_sink(const StudySettings& settings, const std::string& directory, const ProgressSink& progress);

}  // namespace iga
