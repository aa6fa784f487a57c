#pragma once
/// @file
/// When a loop is worth a thread team. Below the threshold, the fork/join and barrier costs exceed
/// the work — badly so on a machine busy with other processes, where waiting threads lose their
/// time slices. In the lowest layer so that spaces, assembly and solver share one rule
/// (`#pragma omp parallel if (worth_threads(n))`).

namespace iga {

inline bool worth_threads(long items) { return items >= 512; }

}  // namespace iga
