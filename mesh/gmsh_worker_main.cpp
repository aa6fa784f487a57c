// The Gmsh worker (see mesh/gmsh_worker.hpp): reads one job from standard input, limits and
// confines itself, runs the job with the Gmsh SDK and writes the result to standard output.

#include <gmsh.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <new>
#include <string>

#include "config/config_node.hpp"
#include "config/errors.hpp"
#include "mesh/gmsh_job.hpp"
#include "mesh/gmsh_session.hpp"
#include "mesh/worker_sandbox.hpp"

namespace {

int result_fd = 1;
std::string out_of_memory_message;

void write_all(int fd, const std::string& bytes) {
  for (std::size_t done = 0; done < bytes.size();) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;
    done += static_cast<std::size_t>(n);
  }
}

/// Allocation failure at the memory limit: say so and end (Gmsh cannot recover from it).
void out_of_memory() {
  ::write(result_fd, out_of_memory_message.data(), out_of_memory_message.size());
  ::_exit(4);
}

}  // namespace

int main() {
  std::string request;
  char buffer[65536];
  for (ssize_t n; (n = ::read(0, buffer, sizeof buffer)) != 0;) {
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return 3;
    request.append(buffer, static_cast<std::size_t>(n));
  }
  iga::GmshJob job;
  try {
    job = iga::decode_job(request);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "iga-gmsh-worker: %s\n", e.what());
    return 3;
  }
  // The result goes to a copy of standard output; whatever Gmsh prints goes to standard error.
  result_fd = ::dup(1);
  ::dup2(2, 1);
  out_of_memory_message = iga::encode_error_result(
      job.source + ": gmsh needed more memory than the limit of " +
      iga::format_number(static_cast<double>(job.limits.memory_bytes) / (1 << 30)) + " GiB (a mesh too fine?)");
  try {
    iga::limit_worker_resources(job.limits);
    std::set_new_handler(out_of_memory);
    iga::with_gmsh(job.source, [] {});  // starts Gmsh before the confinement
    gmsh::option::setNumber("General.Terminal", 1);
    gmsh::option::setNumber("General.Verbosity", 1);  // errors only, for crash messages
    iga::confine_worker(job.readable_folders);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "iga-gmsh-worker: %s\n", e.what());
    return 3;
  }
  std::string result;
  try {
    result = job.surface ? iga::encode_surface_result(iga::run_gmsh_surface_job_here(job))
                         : iga::encode_mesh_result(iga::run_gmsh_job_here(job));
  } catch (const iga::InputError& e) {
    result = iga::encode_error_result(e.what());
  } catch (const std::exception& e) {
    result = iga::encode_error_result(job.source + ": gmsh: " + e.what());
  }
  write_all(result_fd, result);
  ::_exit(0);  // no static destructors: Gmsh's finalisation has nothing to give back
}
