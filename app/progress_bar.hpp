#pragma once
/// @file
/// The command line's view of long phases: on a terminal, a bar with rate and estimated time left
/// that redraws one line of stderr; elsewhere (a log file, a pipe) nothing beyond the one line per
/// phase the study prints itself.

#include <cstdint>
#include <string>

#include "config/progress.hpp"

namespace iga {

class TerminalProgressBar : public ProgressListener {
 public:
  void started(const std::string& phase, std::int64_t total) override;
  void advanced(std::int64_t done, std::int64_t total, double seconds) override;
  void finished(const std::string& phase, double seconds) override;

 private:
  std::string phase_;
  bool drawn_ = false;
};

/// The bar when stderr is a terminal, else nullptr.
ProgressListener* terminal_progress_bar();

}  // namespace iga
