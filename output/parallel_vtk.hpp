#pragma once
/// @file
/// VTK output of a distributed run (mpirun with more than one rank): each rank writes the elements
/// of its partition (the partition of the distributed solve, solver/petsc_partition.hpp) as one piece
/// `<name>_<rank>.vtu`, and rank 0 the index `<name>.pvtu` that ParaView opens as one dataset, both
/// through VTK's parallel XML writer. The pieces carry the same fields as a serial .vtu; the cell
/// field `element` keeps the global element numbers.
///
/// All ranks write into the directory rank 0 stages its outputs in (shared_output_directory), so
/// that directory must be visible to every rank: on one machine the temporary directory is; on a
/// cluster TMPDIR must name a file system all nodes share.

#include <Eigen/Core>
#include <string>

#include "output/vtk_writer.hpp"
#include "spaces/space.hpp"

namespace iga {

/// True when the solution is written as a .pvtu: more than one MPI rank.
bool parallel_vtk_output();

/// Collective: rank 0's output directory `root_directory` on every rank (the others' arguments
/// are ignored). InputError on every rank if some rank cannot see it as a directory.
std::string shared_output_directory(const std::string& root_directory);

/// Collective: write `pvtu_filename` (rank 0) and this rank's piece beside it. Returns, as
/// write_solution_vtu, whether rank 0's elements were drawn as Lagrange cells. Throws on every rank
/// (on_every_rank) if any rank fails.
bool write_solution_pvtu(const Space& space, const Eigen::VectorXd& coefficients, const VtkFieldOptions& options,
                         const std::string& pvtu_filename);

/// Remove a dataset written by write_solution_vtu or write_solution_pvtu: the file and, for a
/// .pvtu, the pieces of every rank.
void remove_solution_dataset(const std::string& filename);

}  // namespace iga
