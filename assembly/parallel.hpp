#pragma once
/// @file
/// When a loop is worth a thread team. Below the threshold, the fork/join and barrier costs exceed
/// the work — badly so on a machine busy with other processes, where waiting threads lose their
/// time slices. Every OpenMP region of assembly/ uses `#pragma omp parallel if (worth_threads(n))`.

#include <Eigen/Core>

namespace iga {

inline bool worth_threads(long items) { return items >= 512; }

/// Eigen's products stay on the calling thread. Our element loops are the parallel level; below
/// worth_threads they run serially on purpose, and Eigen would otherwise start its own OpenMP
/// team inside every element product (a small G1 assembly took 20 times longer with two threads).
/// The setting is global and cheap: every element loop calls this before it starts.
inline void keep_eigen_serial() { Eigen::setNbThreads(1); }

}  // namespace iga
