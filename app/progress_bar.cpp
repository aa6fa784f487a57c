#include "app/progress_bar.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace iga {

namespace {

std::string clock_text(double seconds) {
  char buf[32];
  const long s = static_cast<long>(seconds + 0.5);
  std::snprintf(buf, sizeof buf, "%ld:%02ld", s / 60, s % 60);
  return buf;
}

}  // namespace

void TerminalProgressBar::started(const std::string& phase, std::int64_t total) {
  phase_ = phase;
  drawn_ = false;
  if (total == 0) {  // no units to count: say what runs, the finish line says how long it took
    std::fprintf(stderr, "\r\033[K  %s ...", phase.c_str());
    std::fflush(stderr);
    drawn_ = true;
  }
}

void TerminalProgressBar::advanced(std::int64_t done, std::int64_t total, double seconds) {
  if (total <= 0) return;
  constexpr int width = 30;
  const double fraction = std::min(1.0, static_cast<double>(done) / static_cast<double>(total));
  const int filled = static_cast<int>(fraction * width);
  const double rate = seconds > 0 ? done / seconds : 0.0;
  const double eta = rate > 0 ? (total - done) / rate : 0.0;
  std::fprintf(stderr, "\r\033[K  %-14s [%s%s] %3d%%  %.3g/s  ETA %s", phase_.c_str(), std::string(filled, '#').c_str(),
               std::string(width - filled, '.').c_str(), static_cast<int>(100 * fraction), rate,
               clock_text(eta).c_str());
  std::fflush(stderr);
  drawn_ = true;
}

void TerminalProgressBar::finished(const std::string&, double) {
  if (drawn_) std::fprintf(stderr, "\r\033[K");  // the study's own message line follows
  std::fflush(stderr);
  drawn_ = false;
}

ProgressListener* terminal_progress_bar() {
  static TerminalProgressBar bar;
  return ::isatty(STDERR_FILENO) ? &bar : nullptr;
}

}  // namespace iga
