#pragma once
/// @file
/// What the Gmsh worker does to itself before Gmsh reads any input, so that a hostile script or
/// mesh file cannot reach outside it (the static script check is the first line, this the second).

#include <string>
#include <vector>

#include "mesh/mesh_limits.hpp"

namespace iga {

/// Address space (limits.memory_bytes; not in AddressSanitizer builds), CPU time (limits.seconds;
/// SIGXCPU, then SIGKILL one second later), no core dumps, and the worker dies with its parent.
void limit_worker_resources(const MeshLimits& limits);

/// No file growth (RLIMIT_FSIZE 0: nothing can be written to a file). A system-call filter
/// (seccomp, via libseccomp; applies to root too): no exec, no new processes
/// (threads are allowed), no opening files for writing or creating them, no removing, renaming,
/// linking or changing files or folders, no sockets, no signals to other processes, no ptrace, no
/// raising limits, no io_uring. Then, where the kernel has Landlock, files may only be read inside
/// `readable_folders`. Throws std::runtime_error if the filter cannot be installed.
void confine_worker(const std::vector<std::string>& readable_folders);

}  // namespace iga
