#pragma once
/// @file
/// Progress of long phases (space construction, assembly, factorization, error norms, VTK), for a
/// listener such as the command line's progress bar. Code that does the work marks a phase with
/// a ProgressPhase and each unit of work with progress_tick(); both cost one atomic load when
/// nobody listens, so they may sit inside element loops run by many threads.

#include <cstdint>
#include <string>

namespace iga {

/// Receives the progress of phases. Called from whichever thread did the work, one call at a time.
class ProgressListener {
 public:
  virtual ~ProgressListener() = default;
  /// A phase begins; `total` units of work, or 0 when unknown (e.g. a factorization).
  virtual void started(const std::string& phase, std::int64_t total) = 0;
  /// `done` of `total` units finished after `seconds` (at most every tenth of a second).
  virtual void advanced(std::int64_t done, std::int64_t total, double seconds) = 0;
  /// The phase ended after `seconds`.
  virtual void finished(const std::string& phase, double seconds) = 0;
};

/// Install the process-wide listener (nullptr: none). Not while a phase runs.
void set_progress_listener(ProgressListener* listener);

/// A phase for as long as the object lives. Phases do not nest: an inner phase started while one
/// runs is ignored (the outer one keeps reporting).
class ProgressPhase {
 public:
  ProgressPhase(const std::string& name, std::int64_t total);
  ~ProgressPhase();
  ProgressPhase(const ProgressPhase&) = delete;
  ProgressPhase& operator=(const ProgressPhase&) = delete;

 private:
  bool active_ = false;
};

/// `units` of work of the current phase are done (thread-safe; nothing when no phase runs).
void progress_tick(std::int64_t units = 1);

}  // namespace iga
