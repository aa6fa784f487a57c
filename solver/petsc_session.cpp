// The PETSc session and the collectives of petsc_session.hpp, forwarded to the PETSc runtime
// (petsc_runtime.hpp) once it is loaded; one rank's answers before.
#include "solver/petsc_session.hpp"

#include <cctype>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <string_view>
#include <vector>

#include "solver/petsc_runtime.hpp"

namespace iga {

namespace {
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

std::string messaging_layers_to_skip(const char* world_size, const char* local_size, const char* chosen_pml,
                                     const char* chosen_mtl) {
  if (!world_size || !local_size || std::string_view(world_size) != local_size) return {};
  if (chosen_pml || chosen_mtl) return {};
  return "^cm";
}

namespace {
/// The PETSc part of the command line until the runtime is loaded (it keeps its own copy).
std::vector<std::string> pending_words{"iga-run"};
bool session_exists = false;

/// Launched by mpirun/mpiexec (Open MPI, MPICH, PMIx): every rank needs MPI from the start.
bool launched_by_mpi() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"})
    if (std::getenv(name)) return true;
  return false;
}

/// The runtime, loaded and given the command line's PETSc words the first time it is asked for.
PetscRuntime& runtime() {
  static PetscRuntime* r = [] {
    PetscRuntime* loaded = petsc_runtime(true);
    loaded->set_arguments(pending_words, session_exists);
    return loaded;
  }();
  return *r;
}

/// The runtime if it runs PETSc already; nothing is loaded to answer a question about ranks.
const PetscRuntime* running() {
  const PetscRuntime* r = petsc_runtime(false);
  return r && r->up() ? r : nullptr;
}
}  // namespace

PetscSession::PetscSession(int& argc, char** argv) {
  const auto [own, petsc] = split_petsc_arguments(std::vector<std::string>(argv, argv + argc));
  pending_words = petsc;
  session_exists = true;
  // A serial run loads PETSc and starts MPI only when a solve asks for PETSc
  // (ensure_petsc_initialised): a run with CHOLMOD never loads their libraries (start-up) nor
  // touches MPI (no session files in TMPDIR).
  if (launched_by_mpi()) {
    // Before MPI_Init, which reads it; every rank decides alike from its launch environment.
    const std::string pml = messaging_layers_to_skip(std::getenv("OMPI_COMM_WORLD_SIZE"),
                                                     std::getenv("OMPI_COMM_WORLD_LOCAL_SIZE"),
                                                     std::getenv("OMPI_MCA_pml"), std::getenv("OMPI_MCA_mtl"));
    if (!pml.empty()) setenv("OMPI_MCA_pml", pml.c_str(), 0);
    try {
      runtime().ensure_initialised();
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

PetscSession::~PetscSession() {
  if (!running()) {
    if (pending_words.size() > 1)
      std::cerr << "iga-run: warning: PETSc options given but not used: the solver is not solver.type: petsc\n";
    return;
  }
  runtime().end_session();
}

int mpi_rank() { return running() ? running()->rank() : 0; }
int mpi_size() { return running() ? running()->size() : 1; }
int ranks_on_this_node() { return running() ? running()->ranks_on_this_node() : 1; }
double sum_over_ranks(double value) { return running() ? running()->sum(value) : value; }
double max_over_ranks(double value) { return running() ? running()->max(value) : value; }
double first_known_over_ranks(double value) { return running() ? running()->first_known(value) : value; }
std::vector<double> gather_over_ranks(const std::vector<double>& mine) {
  return running() ? running()->gather(mine) : mine;
}
void on_every_rank(const std::function<void()>& work) { running() ? running()->on_every_rank(work) : work(); }
std::string broadcast_from_root(const std::string& text) {
  return running() ? running()->broadcast_from_root(text) : text;
}
bool failure_shared_by_all_ranks() { return running() && running()->failure_shared_by_all_ranks(); }
int end_ranks_after_failure(int code) { return running() ? running()->end_ranks_after_failure(code) : code; }
void before_mpi_finalize(std::function<void()> release) {
  if (running()) runtime().before_mpi_finalize(std::move(release));
}
void ensure_petsc_initialised() { runtime().ensure_initialised(); }

}  // namespace iga
