#include "mesh/gmsh_worker.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <list>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <type_traits>

#include "config/companion_file.hpp"
#include "config/config_node.hpp"
#include "config/errors.hpp"

extern char** environ;

namespace iga {

namespace {

namespace fs = std::filesystem;

constexpr const char* worker_name = "iga-gmsh-worker";

fs::path worker_path() {
  std::vector<std::string> compiled_in;
#ifdef IGA_GMSH_WORKER_PATH
  compiled_in.push_back(IGA_GMSH_WORKER_PATH);
#endif
  // Programs built against the installed package (and the Python module) run from elsewhere.
#ifdef IGA_GMSH_WORKER_INSTALLED_PATH
  compiled_in.push_back(IGA_GMSH_WORKER_INSTALLED_PATH);
#endif
  return find_companion_file("the Gmsh worker", worker_name, {}, compiled_in);
}

/// A file descriptor closed when it goes out of scope.
struct Fd {
  int fd = -1;
  Fd() = default;
  explicit Fd(int f) : fd(f) {}
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;
  ~Fd() { reset(); }
  void reset() {
    if (fd >= 0) ::close(fd);
    fd = -1;
  }
};

struct Channel {
  Fd parent, child;
};

/// A pipe (from the worker) or, for its input, a socket pair: writing to a socket can refuse
/// SIGPIPE per call (MSG_NOSIGNAL), so a worker that dies early cannot kill the caller.
Channel make_channel(bool socket) {
  int fds[2];
  const int rc = socket ? ::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, fds) : ::pipe2(fds, O_CLOEXEC);
  if (rc != 0)
    throw std::runtime_error(std::string("cannot create a pipe for the Gmsh worker: ") + std::strerror(errno));
  return Channel{Fd(fds[0]), Fd(fds[1])};
}

/// The lines Gmsh printed on its error stream that name an error (for crash messages); else the
/// C++ runtime's last words.
std::string gmsh_errors(const std::string& err) {
  std::string errors, runtime;
  std::size_t start = 0;
  while (start < err.size()) {
    std::size_t end = err.find('\n', start);
    if (end == std::string::npos) end = err.size();
    std::string line = err.substr(start, end - start);
    for (std::size_t at; (at = line.find("  ")) != std::string::npos;) line.erase(at, 1);
    std::string& kind = line.find("Error") != std::string::npos ? errors : runtime;
    if (&kind == &errors || line.find("terminate") != std::string::npos || line.find("what()") != std::string::npos)
      kind = kind.empty() ? line : kind + "; " + line;
    start = end + 1;
  }
  std::string found = errors.empty() ? runtime : errors;
  if (found.size() > 400) found = "..." + found.substr(found.size() - 400);
  return found;
}

std::string describe_signal(int sig, const MeshLimits& limits) {
  if (sig == SIGXCPU) return "reached the CPU time limit of " + format_number(limits.seconds) + " s";
  if (sig == SIGKILL) return "was killed (signal SIGKILL; out of memory?)";
  const char* name = ::sigabbrev_np(sig);
  return std::string("crashed (signal SIG") + (name ? name : std::to_string(sig).c_str()) + ")";
}

/// Runs `job` in a worker and returns its result message (checked: not an error).
std::string run_worker(const GmshJob& job) {
  const fs::path worker = worker_path();
  Channel input = make_channel(true), output = make_channel(false), errors = make_channel(false);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  // input: socketpair, the child's end is fds[1]; output and errors: pipes, the child writes fds[1].
  posix_spawn_file_actions_adddup2(&actions, input.child.fd, 0);
  posix_spawn_file_actions_adddup2(&actions, output.child.fd, 1);
  posix_spawn_file_actions_adddup2(&actions, errors.child.fd, 2);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  // Its own process group (killed as a whole), no blocked signals and default actions for the
  // signals that end it at its limits or crashes, whatever the caller set for itself.
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);
  posix_spawnattr_setpgroup(&attributes, 0);
  sigset_t none, defaults;
  sigemptyset(&none);
  sigemptyset(&defaults);
  for (int sig : {SIGXCPU, SIGPIPE, SIGSEGV, SIGABRT, SIGBUS, SIGFPE}) sigaddset(&defaults, sig);
  posix_spawnattr_setsigmask(&attributes, &none);
  posix_spawnattr_setsigdefault(&attributes, &defaults);
  const std::string program = worker.string();
  char* argv[] = {const_cast<char*>(program.c_str()), nullptr};
  pid_t pid = 0;
  const int spawned = ::posix_spawn(&pid, program.c_str(), &actions, &attributes, argv, environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  if (spawned != 0) throw std::runtime_error("cannot start the Gmsh worker " + program + ": " + std::strerror(spawned));
  input.child.reset();
  output.child.reset();
  errors.child.reset();

  const std::string request = encode_job(job);
  for (std::size_t sent = 0; sent < request.size();) {
    const ssize_t n = ::send(input.parent.fd, request.data() + sent, request.size() - sent, MSG_NOSIGNAL);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;  // the worker died; its status says why
    sent += static_cast<std::size_t>(n);
  }
  input.parent.reset();

  std::string out, err;
  bool timed_out = false;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(job.limits.seconds);
  for (bool out_open = true, err_open = true; out_open || err_open;) {
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) {
      timed_out = true;
      ::kill(-pid, SIGKILL);
      break;
    }
    pollfd fds[2] = {{out_open ? output.parent.fd : -1, POLLIN, 0}, {err_open ? errors.parent.fd : -1, POLLIN, 0}};
    const int ready = ::poll(fds, 2, static_cast<int>(std::min<long long>(left.count(), 1000)));
    if (ready < 0 && errno != EINTR) break;
    char buffer[65536];
    for (int k = 0; k < 2; ++k) {
      if (!(fds[k].revents & (POLLIN | POLLHUP | POLLERR))) continue;
      const ssize_t n = ::read(fds[k].fd, buffer, sizeof buffer);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) {
        (k == 0 ? out_open : err_open) = false;
        continue;
      }
      if (k == 0) {
        out.append(buffer, static_cast<std::size_t>(n));
      } else {
        err.append(buffer, static_cast<std::size_t>(n));
        if (err.size() > 65536) err.erase(0, err.size() - 32768);  // keep the end
      }
    }
  }
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  ::kill(-pid, SIGKILL);  // anything the worker left in its group (it may start nothing, but be sure)

  const std::string& source = job.source;
  if (timed_out)
    throw InputError(source + ": gmsh did not finish within the time limit of " + format_number(job.limits.seconds) +
                     " s (an endless loop in the script, or a mesh too fine)");
  if (!out.empty() && out[0] == 'E' && WIFEXITED(status)) throw InputError(out.substr(1));
  if (WIFSIGNALED(status)) {
    const std::string said = gmsh_errors(err);
    throw InputError(source + ": gmsh " + describe_signal(WTERMSIG(status), job.limits) +
                     (said.empty() ? "" : ": " + said));
  }
  if (out.empty() || WEXITSTATUS(status) != 0) {
    const std::string said = gmsh_errors(err);
    throw InputError(source + ": gmsh ended without a mesh (exit status " + std::to_string(WEXITSTATUS(status)) +
                     (out.empty() && WEXITSTATUS(status) == 0 ? ": the script ended Gmsh early" : "") + ")" +
                     (said.empty() ? "" : ": " + said));
  }
  return out;
}

template <class Mesh>
Mesh decoded(const std::string& out, const std::string& source) {
  try {
    if constexpr (std::is_same_v<Mesh, PlanarMesh>)
      return decode_mesh(out, source);
    else
      return decode_surface(out, source);
  } catch (const std::runtime_error& e) {
    throw InputError(source + ": gmsh worker sent a broken mesh (" + e.what() + ")");
  }
}

template <class Mesh>
Mesh run_cached(const GmshJob& job, const std::vector<fs::path>& input_files) {
  std::string key = encode_job(job);
  for (const auto& file : input_files) {
    std::ifstream in(file, std::ios::binary);
    std::stringstream bytes;
    bytes << in.rdbuf();
    key += '\0' + file.string() + '\0' + std::to_string(bytes.str().size()) + '\0' + bytes.str();
  }
  static std::mutex lock;
  static std::list<std::pair<std::string, Mesh>> recent;  // newest first, at most 4
  {
    const std::lock_guard<std::mutex> guard(lock);
    for (const auto& [k, mesh] : recent)
      if (k == key) return mesh;
  }
  Mesh mesh = decoded<Mesh>(run_worker(job), job.source);
  const std::lock_guard<std::mutex> guard(lock);
  recent.emplace_front(std::move(key), mesh);
  if (recent.size() > 4) recent.pop_back();
  return mesh;
}

}  // namespace

PlanarMesh run_gmsh_job(const GmshJob& job) { return decoded<PlanarMesh>(run_worker(job), job.source); }

SurfaceMeshFile run_gmsh_surface_job(const GmshJob& job) {
  return decoded<SurfaceMeshFile>(run_worker(job), job.source);
}

PlanarMesh run_gmsh_job_cached(const GmshJob& job, const std::vector<fs::path>& input_files) {
  return run_cached<PlanarMesh>(job, input_files);
}

SurfaceMeshFile run_gmsh_surface_job_cached(const GmshJob& job, const std::vector<fs::path>& input_files) {
  return run_cached<SurfaceMeshFile>(job, input_files);
}

}  // namespace iga
