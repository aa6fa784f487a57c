#include "solver/petsc_session.hpp"

#include <cctype>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <vector>

#include "config/errors.hpp"

#ifdef IGA_WITH_PETSC
#include <petscsys.h>
#include <unistd.h>
#endif

namespace iga {

namespace {
bool shared_failure = false;

bool is_petsc_option(const std::string& word) {
  if (word == "-info") return true;
  if (word.size() < 3 || word[0] != '-' || !std::isalpha(static_cast<unsigned char>(word[1]))) return false;
  return word.find('_') != std::string::npos && word.find('=') == std::string::npos;
}

bool is_negative_number(const std::string& word) {
  return word.size() > 1 && word[0] == '-' && (std::isdigit(static_cast<unsigned char>(word[1])) || word[1] == '.');
}

/// iga-run's own options that take a value (the value is not a positional argument).
bool takes_value(const std::string& word) { return word == "-o" || word == "--output" || word == "-l" || word == "--levels"; }

#ifdef IGA_WITH_PETSC
/// Options nothing used, one line each on rank 0: PETSc ignores a misspelt option silently.
void report_unused_options() {
  PetscInt n = 0;
  char** names = nullptr;
  char** values = nullptr;
  if (PetscOptionsLeftGet(nullptr, &n, &names, &values) != 0) return;
  if (is_root_rank())
    for (PetscInt i = 0; i < n; ++i)
      std::cerr << "iga-run: warning: PETSc option -" << names[i] << (values[i] ? std::string(" ") + values[i] : "")
                << " was not used (unknown, misspelt, or not for this solver)\n";
  PetscOptionsLeftRestore(nullptr, &n, &names, &values);
}
#endif
}  // namespace

std::pair<std::vector<std::string>, std::vector<std::string>> split_petsc_arguments(
    const std::vector<std::string>& args) {
  std::vector<std::string> own, petsc;
  if (!args.empty()) {
    own.push_back(args[0]);
    petsc.push_back(args[0]);
  }
  bool config_seen = false;
  for (std::size_t i = 1; i < args.size(); ++i) {
    const std::string& w = args[i];
    if (is_petsc_option(w)) {
      petsc.push_back(w);
      if (i + 1 < args.size()) {
        const std::string& next = args[i + 1];
        const bool looks_like_config = !config_seen && (next.ends_with(".yaml") || next.ends_with(".yml"));
        if ((next.empty() || next[0] != '-' || is_negative_number(next)) && !looks_like_config) petsc.push_back(args[++i]);
      }
      continue;
    }
    own.push_back(w);
    if (takes_value(w) && i + 1 < args.size()) {
      own.push_back(args[++i]);
    } else if (!w.empty() && w[0] != '-') {
      config_seen = true;
    }
  }
  return {own, petsc};
}

#ifdef IGA_WITH_PETSC

namespace {
/// The PETSc part of the command line, kept for a later initialisation: PETSc keeps pointers into
/// its argv, so these live as long as the program.
struct PendingArguments {
  std::vector<std::string> words{"iga-run"};
  std::vector<char*> argv;
  bool session = false;  ///< a PetscSession exists and will finalise
} pending;

/// Launched by mpirun/mpiexec (Open MPI, MPICH, PMIx): every rank needs MPI from the start.
bool launched_by_mpi() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"})
    if (std::getenv(name)) return true;
  return false;
}

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

/// PETSc reads ~/.petscrc, ./.petscrc and ./petscrc unless -skip_petscrc is given: a file beside a
/// downloaded config could then set any option (-log_view :FILE writes a file). -skip_petscrc
/// first (a later -skip_petscrc of the user still decides), and the home file, the user's own,
/// given as PETSc's options file, which it reads with the precedence it would have had.
void initialise_with_pending_arguments() {
  static std::string skip = "-skip_petscrc";
  static std::string home_file;
  home_file = home_options_file();
  if (pending.words.empty()) pending.words.push_back("iga-run");
  pending.argv.clear();
  pending.argv.push_back(pending.words[0].data());
  pending.argv.push_back(skip.data());
  for (std::size_t i = 1; i < pending.words.size(); ++i) pending.argv.push_back(pending.words[i].data());
  pending.argv.push_back(nullptr);
  int argc = static_cast<int>(pending.argv.size()) - 1;
  char** argv = pending.argv.data();
  if (PetscInitialize(&argc, &argv, home_file.c_str(), nullptr) != 0) throw std::runtime_error("PETSc failed to initialise");
  // PETSc's signal handlers would turn a closed pipe (iga-run ... | head) into a crash report.
  PetscPopSignalHandler();
}
}  // namespace

PetscSession::PetscSession(int& argc, char** argv) {
  const auto [own, petsc] = split_petsc_arguments(std::vector<std::string>(argv, argv + argc));
  pending.words = petsc;
  pending.session = true;
  // A serial run starts MPI only when a solve asks for PETSc (ensure_petsc_initialised): a run
  // with CHOLMOD then never touches MPI (no start-up cost, no session files in TMPDIR).
  if (launched_by_mpi()) {
    try {
      initialise_with_pending_arguments();
    } catch (const std::exception& e) {
      std::cerr << "iga-run: error: " << e.what() << '\n';
      std::exit(1);
    }
  }
  // iga-run's own arguments back into argv (they are a subsequence of it, so they fit).
  static std::vector<std::string> own_words;
  own_words = own;
  argc = static_cast<int>(own_words.size());
  for (int i = 0; i < argc; ++i) argv[i] = own_words[i].data();
  argv[argc] = nullptr;
}

namespace {
std::vector<std::function<void()>> releases_before_finalize;

void finalize_petsc() {
  while (!releases_before_finalize.empty()) {
    const std::function<void()> release = std::move(releases_before_finalize.back());
    releases_before_finalize.pop_back();
    release();
  }
  PetscFinalize();
}
}  // namespace

void before_mpi_finalize(std::function<void()> release) { releases_before_finalize.push_back(std::move(release)); }

PetscSession::~PetscSession() {
  if (!petsc_up()) {
    if (pending.words.size() > 1)
      std::cerr << "iga-run: warning: PETSc options given but not used: the solver is not solver.type: petsc\n";
    return;
  }
  report_unused_options();
  finalize_petsc();
}

int mpi_rank() {
  if (!petsc_up()) return 0;
  PetscMPIInt rank = 0;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  return rank;
}

int mpi_size() {
  if (!petsc_up()) return 1;
  PetscMPIInt size = 1;
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  return size;
}

double sum_over_ranks(double value) {
  if (!petsc_up()) return value;
  MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_DOUBLE, MPI_SUM, PETSC_COMM_WORLD);
  return value;
}

double max_over_ranks(double value) {
  if (!petsc_up()) return value;
  MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_DOUBLE, MPI_MAX, PETSC_COMM_WORLD);
  return value;
}

double first_known_over_ranks(double value) {
  if (!petsc_up()) return value;
  int from = std::isnan(value) ? INT_MAX : mpi_rank();
  MPI_Allreduce(MPI_IN_PLACE, &from, 1, MPI_INT, MPI_MIN, PETSC_COMM_WORLD);
  if (from == INT_MAX) return value;  // no rank has one: NaN everywhere
  MPI_Bcast(&value, 1, MPI_DOUBLE, from, PETSC_COMM_WORLD);
  return value;
}

int ranks_on_this_node() {
  if (!petsc_up()) return 1;
  MPI_Comm node = MPI_COMM_NULL;
  MPI_Comm_split_type(PETSC_COMM_WORLD, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
  int size = 1;
  MPI_Comm_size(node, &size);
  MPI_Comm_free(&node);
  return size;
}

void on_every_rank(const std::function<void()>& work) {
  if (!petsc_up()) return work();
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
  const int rank = mpi_rank(), size = mpi_size();
  int first = code ? rank : size;
  MPI_Allreduce(MPI_IN_PLACE, &first, 1, MPI_INT, MPI_MIN, PETSC_COMM_WORLD);
  if (first == size) return;
  // The lowest failing rank tells the others what happened.
  int header[2] = {code, static_cast<int>(message.size())};
  MPI_Bcast(header, 2, MPI_INT, first, PETSC_COMM_WORLD);
  message.resize(header[1]);
  MPI_Bcast(message.data(), header[1], MPI_CHAR, first, PETSC_COMM_WORLD);
  shared_failure = true;
  if (header[0] == 2) throw InputError(message);
  if (header[0] == 1) throw NumericalError(message);
  throw std::runtime_error(message);
}

std::string broadcast_from_root(const std::string& text) {
  if (!petsc_up()) return text;
  std::string out = text;
  int size = static_cast<int>(out.size());
  MPI_Bcast(&size, 1, MPI_INT, 0, PETSC_COMM_WORLD);
  out.resize(size);
  MPI_Bcast(out.data(), size, MPI_CHAR, 0, PETSC_COMM_WORLD);
  return out;
}

bool failure_shared_by_all_ranks() { return shared_failure; }

int end_ranks_after_failure(int code) {
  if (mpi_size() > 1 && !shared_failure) MPI_Abort(PETSC_COMM_WORLD, code);
  return code;
}

void ensure_petsc_initialised() {
  if (petsc_up()) return;
  initialise_with_pending_arguments();
  if (!pending.session) std::atexit(finalize_petsc);  // a program without a session (tests)
}

#else  // without PETSc: one rank, nothing to initialise

PetscSession::PetscSession(int&, char**) {}
PetscSession::~PetscSession() = default;
int mpi_rank() { return 0; }
int mpi_size() { return 1; }
int ranks_on_this_node() { return 1; }
double sum_over_ranks(double value) { return value; }
double max_over_ranks(double value) { return value; }
double first_known_over_ranks(double value) { return value; }
void on_every_rank(const std::function<void()>& work) { work(); }
std::string broadcast_from_root(const std::string& text) { return text; }
bool failure_shared_by_all_ranks() { return false; }
int end_ranks_after_failure(int code) { return code; }
void ensure_petsc_initialised() {}
void before_mpi_finalize(std::function<void()>) {}

#endif

}  // namespace iga
