#pragma once
/// @file
/// Access to the Gmsh SDK, which is a process-wide singleton and not thread-safe: gmsh is
/// initialised once per process (terminal output off, no user config files, one thread) and
/// finalised at exit; every use holds one lock and starts from an empty model. Only the Gmsh
/// worker process calls Gmsh (gmsh_worker.hpp): a Gmsh failure must never reach the caller's
/// process, and General.NumThreads would set the OpenMP thread count of the whole process.

#include <functional>
#include <string>

namespace iga {

/// Runs `work` with Gmsh initialised, locked and cleared (cleared again afterwards). Anything Gmsh
/// throws becomes an InputError "<source>: gmsh: <message>"; InputErrors from `work` pass through.
void with_gmsh(const std::string& source, const std::function<void()>& work);

}  // namespace iga
