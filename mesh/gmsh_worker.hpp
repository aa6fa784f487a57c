#pragma once
/// @file
/// Gmsh runs in a child process, the Gmsh worker (`iga-gmsh-worker`, gmsh_worker_main.cpp), so
/// that its failures and limits are ours to handle: a crash (a Gmsh error thrown inside an OpenMP
/// region aborts), an `Exit` in a script, an endless loop or an allocation without bound ends the
/// worker, never the caller. The worker is a fresh process (spawned, not forked: the caller may
/// already have run OpenMP regions), limits its own memory and CPU time, and confines itself
/// before Gmsh reads anything (worker_sandbox.hpp); the caller kills it at the wall-clock limit.

#include <filesystem>
#include <vector>

#include "mesh/gmsh_job.hpp"
#include "mesh/planar_mesh.hpp"

namespace iga {

/// Runs `job` in a Gmsh worker and returns its mesh. Every failure is an InputError naming
/// job.source: Gmsh's own error messages, a time or memory limit reached, a worker ended by a
/// signal or ended early. A worker that cannot be found or started is a std::runtime_error (an
/// installation problem, not an input one). The worker is looked for next to the running
/// executable, then at the path of the build that compiled this library.
PlanarMesh run_gmsh_job(const GmshJob& job);

/// run_gmsh_job, remembering the last few meshes by the job and the contents of `input_files`
/// (everything Gmsh reads for it): a study that builds its space once per level meshes the same
/// file once. Failures are not remembered.
PlanarMesh run_gmsh_job_cached(const GmshJob& job, const std::vector<std::filesystem::path>& input_files);

/// The same for jobs with `surface` set: a triangle mesh in 3D.
SurfaceMeshFile run_gmsh_surface_job(const GmshJob& job);
SurfaceMeshFile run_gmsh_surface_job_cached(const GmshJob& job,
                                            const std::vector<std::filesystem::path>& input_files);

}  // namespace iga
