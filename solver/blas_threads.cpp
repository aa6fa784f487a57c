#include "solver/blas_threads.hpp"

#include <dlfcn.h>
#include <omp.h>

#include <cstdlib>

namespace iga {

void set_blas_threads(int threads) {
  using SetThreads = void (*)(int);
  static const SetThreads set = [] {
    if (std::getenv("OPENBLAS_NUM_THREADS") || std::getenv("GOTO_NUM_THREADS")) return SetThreads{nullptr};
    return reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
  }();
  if (set) set(threads);
}

void set_blas_threads_for(int unknowns) { set_blas_threads(unknowns < kParallelBlasUnknowns ? 1 : omp_get_max_threads()); }

}  // namespace iga
