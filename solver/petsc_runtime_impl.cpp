// The PETSc session and MPI collectives behind petsc_session.hpp (part of the PETSc plugin).
#include <petscsys.h>
#include <unistd.h>

#include <climits>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <vector>

#include "config/errors.hpp"
#include "solver/petsc_runtime.hpp"

namespace iga {

namespace {

bool petsc_up() {
  PetscBool up = PETSC_FALSE;
  PetscInitialized(&up);
  return up == PETSC_TRUE;
}

/// The options file PETSc reads first (below PETSC_OPTIONS and the command line): the user's
/// ~/.petscrc if there is one, else /dev/null. Never empty: PETSc reads the file on rank 0 and
/// broadcasts it, a collective call that every rank must make (an empty name would skip it).
std::string home_options_file() {
  if (const char* home = std::getenv("HOME"); home && *home) {
    std::error_code ec;
    const std::filesystem::path file = std::filesystem::path(home) / ".petscrc";
    // PETSc fails on a named file it cannot read, where it skipped an unreadable ~/.petscrc.
    if (std::filesystem::is_regular_file(file, ec) && ::access(file.c_str(), R_OK) == 0) return file.string();
  }
  return "/dev/null";
}

/// Options nothing used, one line each on rank 0: PETSc ignores a misspelt option silently.
void report_unused_options(int rank) {
  PetscInt n = 0;
  char** names = nullptr;
  char** values = nullptr;
  if (PetscOptionsLeftGet(nullptr, &n, &names, &values) != 0) return;
  if (rank == 0)
    for (PetscInt i = 0; i < n; ++i)
      std::cerr << "iga-run: warning: PETSc option -" << names[i] << (values[i] ? std::string(" ") + values[i] : "")
                << " was not used (unknown, misspelt, or not for this solver)\n";
  PetscOptionsLeftRestore(nullptr, &n, &names, &values);
}

std::vector<std::function<void()>> releases_before_finalize;

void finalize_petsc() {
  while (!releases_before_finalize.empty()) {
    const std::function<void()> release = std::move(releases_before_finalize.back());
    releases_before_finalize.pop_back();
    release();
  }
  PetscFinalize();
}

// Past ensure_initialised, every method is reached only while PETSc runs: petsc_session.cpp asks
// up() before each call (running()), and a PetscSession ends the session only then.
class Runtime final : public PetscRuntime {
 public:
  void set_arguments(std::vector<std::string> words, bool session) override {
    words_ = std::move(words);
    session_ = session;
  }

  /// PETSc reads ~/.petscrc, ./.petscrc and ./petscrc unless -skip_petscrc is given: a file beside a
  /// downloaded config could then set any option (-log_view :FILE writes a file). -skip_petscrc
  /// first (a later -skip_petscrc of the user still decides), and the home file, the user's own,
  /// given as PETSc's options file, which it reads with the precedence it would have had.
  void ensure_initialised() override {
    if (petsc_up()) return;
    home_file_ = home_options_file();
    if (words_.empty()) words_.push_back("iga-run");
    // PETSc keeps pointers into its argv: these live as long as the runtime.
    argv_.clear();
    argv_.push_back(words_[0].data());
    argv_.push_back(skip_.data());
    for (std::size_t i = 1; i < words_.size(); ++i) argv_.push_back(words_[i].data());
    argv_.push_back(nullptr);
    int argc = static_cast<int>(argv_.size()) - 1;
    char** argv = argv_.data();
    if (PetscInitialize(&argc, &argv, home_file_.c_str(), nullptr) != 0)
      throw std::runtime_error("PETSc failed to initialise");
    // PETSc's signal handlers would turn a closed pipe (iga-run ... | head) into a crash report.
    PetscPopSignalHandler();
    if (!session_) std::atexit(finalize_petsc);  // a program without a session (tests)
  }

  bool up() const override { return petsc_up(); }

  void end_session() override {
    report_unused_options(rank());
    finalize_petsc();
  }

  int rank() const override {
    PetscMPIInt rank = 0;
    MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
    return rank;
  }

  int size() const override {
    PetscMPIInt size = 1;
    MPI_Comm_size(PETSC_COMM_WORLD, &size);
    return size;
  }

  int ranks_on_this_node() const override {
    MPI_Comm node = MPI_COMM_NULL;
    MPI_Comm_split_type(PETSC_COMM_WORLD, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
    int size = 1;
    MPI_Comm_size(node, &size);
    MPI_Comm_free(&node);
    return size;
  }

  double sum(double value) const override { return reduce(value, MPI_SUM); }
  double max(double value) const override { return reduce(value, MPI_MAX); }

  double first_known(double value) const override {
    int from = std::isnan(value) ? INT_MAX : rank();
    MPI_Allreduce(MPI_IN_PLACE, &from, 1, MPI_INT, MPI_MIN, PETSC_COMM_WORLD);
    if (from == INT_MAX) return value;  // no rank has one: NaN everywhere
    MPI_Bcast(&value, 1, MPI_DOUBLE, from, PETSC_COMM_WORLD);
    return value;
  }

  std::vector<double> gather(const std::vector<double>& mine) const override {
    const int ranks = size();
    const int count = static_cast<int>(mine.size());
    std::vector<int> counts(ranks), offsets(ranks + 1, 0);
    MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, PETSC_COMM_WORLD);
    for (int r = 0; r < ranks; ++r) offsets[r + 1] = offsets[r] + counts[r];
    std::vector<double> all(offsets[ranks]);
    MPI_Allgatherv(mine.data(), count, MPI_DOUBLE, all.data(), counts.data(), offsets.data(), MPI_DOUBLE,
                   PETSC_COMM_WORLD);
    return all;
  }

  void on_every_rank(const std::function<void()>& work) const override {
    int code = 0;  // 0 ok, 1 numerical, 2 input, 3 other
    std::string message;
    try {
      work();
    } catch (const InputError& e) {
      code = 2, message = e.what();
    } catch (const NumericalError& e) {
      code = 1, message = e.what();
    } catch (const std::exception& e) {
      code = 3, message = e.what();
    }
    const int me = rank(), ranks = size();
    int first = code ? me : ranks;
    MPI_Allreduce(MPI_IN_PLACE, &first, 1, MPI_INT, MPI_MIN, PETSC_COMM_WORLD);
    if (first == ranks) return;
    // The lowest failing rank tells the others what happened.
    int header[2] = {code, static_cast<int>(message.size())};
    MPI_Bcast(header, 2, MPI_INT, first, PETSC_COMM_WORLD);
    message.resize(header[1]);
    MPI_Bcast(message.data(), header[1], MPI_CHAR, first, PETSC_COMM_WORLD);
    shared_failure_ = true;
    if (header[0] == 2) throw InputError(message);
    if (header[0] == 1) throw NumericalError(message);
    throw std::runtime_error(message);
  }

  std::string broadcast_from_root(const std::string& text) const override {
    std::string out = text;
    int n = static_cast<int>(out.size());
    MPI_Bcast(&n, 1, MPI_INT, 0, PETSC_COMM_WORLD);
    out.resize(n);
    MPI_Bcast(out.data(), n, MPI_CHAR, 0, PETSC_COMM_WORLD);
    return out;
  }

  bool failure_shared_by_all_ranks() const override { return shared_failure_; }

  int end_ranks_after_failure(int code) const override {
    if (size() > 1 && !shared_failure_) MPI_Abort(PETSC_COMM_WORLD, code);
    return code;
  }

  void before_mpi_finalize(std::function<void()> release) override {
    releases_before_finalize.push_back(std::move(release));
  }

  std::unique_ptr<LinearBackend> make_linear_backend(const Space& space, const PetscSettings& settings,
                                                     const ProgressSink& progress) override {
    return make_distributed_backend(space, settings, progress);
  }

  std::unique_ptr<EigenBackend> make_eigen_backend(const Space& space, const ProgressSink& progress) override {
    return make_slepc_backend(space, progress);
  }

 private:
  static double reduce(double value, MPI_Op op) {
    MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_DOUBLE, op, PETSC_COMM_WORLD);
    return value;
  }

  std::vector<std::string> words_{"iga-run"};
  bool session_ = false;
  std::string skip_ = "-skip_petscrc";
  std::string home_file_;
  std::vector<char*> argv_;
  mutable bool shared_failure_ = false;
};

}  // namespace

PetscRuntime& petsc_runtime_implementation() {
  static Runtime runtime;
  return runtime;
}

}  // namespace iga
