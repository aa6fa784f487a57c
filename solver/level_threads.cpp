#include "solver/level_threads.hpp"

#include <omp.h>

namespace iga {

LevelThreads::LevelThreads(long long unknowns) : before_(omp_get_max_threads()) {
  if (unknowns < kParallelLevelUnknowns) omp_set_num_threads(1);
}

LevelThreads::~LevelThreads() { omp_set_num_threads(before_); }

}  // namespace iga
