#include "config/progress.hpp"

#include <atomic>
#include <chrono>
#include <mutex>

namespace iga {

namespace {

using Clock = std::chrono::steady_clock;

ProgressListener* listener = nullptr;
std::atomic<bool> running{false};
std::atomic<std::int64_t> done{0};
std::atomic<std::int64_t> next_report_ns{0};  // since `start`
std::int64_t total = 0;
std::string name;
Clock::time_point start;
std::mutex report_mutex;

constexpr std::int64_t kReportEveryNs = 100'000'000;  // a tenth of a second

double elapsed() { return std::chrono::duration<double>(Clock::now() - start).count(); }

}  // namespace

void set_progress_listener(ProgressListener* l) { listener = l; }

ProgressPhase::ProgressPhase(const std::string& phase, std::int64_t units) {
  if (!listener || running.load(std::memory_order_relaxed)) return;
  active_ = true;
  name = phase;
  total = units;
  done.store(0);
  start = Clock::now();
  next_report_ns.store(kReportEveryNs);
  listener->started(name, total);
  running.store(true, std::memory_order_release);
}

ProgressPhase::~ProgressPhase() {
  if (!active_) return;
  running.store(false, std::memory_order_release);
  std::lock_guard<std::mutex> lock(report_mutex);  // wait for a report in flight
  listener->finished(name, elapsed());
}

void progress_tick(std::int64_t units) {
  if (!running.load(std::memory_order_acquire)) return;
  const std::int64_t now_done = done.fetch_add(units, std::memory_order_relaxed) + units;
  const auto ns = std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now() - start).count();
  std::int64_t due = next_report_ns.load(std::memory_order_relaxed);
  if (ns < due || !next_report_ns.compare_exchange_strong(due, ns + kReportEveryNs)) return;
  std::unique_lock<std::mutex> lock(report_mutex, std::try_to_lock);
  if (lock && running.load(std::memory_order_acquire)) listener->advanced(now_done, total, ns * 1e-9);
}

}  // namespace iga
