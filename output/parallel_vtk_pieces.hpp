#pragma once
/// @file
/// Shared by the VTK output of distributed runs (parallel_vtk.cpp) and its MPI writer in the PETSc
/// plugin (parallel_vtk_mpi.cpp).
#include <Eigen/Core>
#include <filesystem>
#include <string>

#include "output/vtk_writer.hpp"

namespace iga {

/// The piece of `rank` beside `pvtu` (VTK's naming: <stem>_<rank>.vtu).
std::filesystem::path piece_path(const std::filesystem::path& pvtu, int rank);

/// write_solution_pvtu's work (parallel_vtk.hpp), in the plugin.
bool write_solution_pvtu_mpi(const Space& space, const Eigen::VectorXd& coefficients, const VtkFieldOptions& options,
                             const std::string& pvtu_filename);

}  // namespace iga
