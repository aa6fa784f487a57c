#pragma once
/// @file
/// OpenMP threads of one level of a study. Opening a team costs a thread start per worker, and
/// after every parallel region libgomp's idle workers spin for their next task (tens of
/// milliseconds of a core in all): on a level of a few thousand unknowns that is more than the
/// second thread saves. The quickstart's one-level study took 0.12 s of wall time with two threads
/// and 0.08 s with one (docs/benchmarks.md, start-up).
namespace iga {

/// Below this many unknowns a level runs on one thread (its work takes milliseconds).
inline constexpr int kParallelLevelUnknowns = 20000;

/// For its lifetime: one OpenMP thread when `unknowns` < kParallelLevelUnknowns, else the
/// threads set before (--threads, OMP_NUM_THREADS, OpenMP's default).
class LevelThreads {
 public:
  explicit LevelThreads(long long unknowns);
  ~LevelThreads();
  LevelThreads(const LevelThreads&) = delete;
  LevelThreads& operator=(const LevelThreads&) = delete;

 private:
  int before_;
};

}  // namespace iga
