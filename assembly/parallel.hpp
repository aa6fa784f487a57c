#pragma once
/// @file
/// Threads in assembly/: every OpenMP region uses `#pragma omp parallel if (worth_threads(n))`
/// (config/worth_threads.hpp), and Eigen stays serial inside them.

#include <Eigen/Core>

#include "config/worth_threads.hpp"

namespace iga {

/// Eigen's products stay on the calling thread. Our element loops are the parallel level; below
/// worth_threads they run serially on purpose, and Eigen would otherwise start its own OpenMP
/// team inside every element product (a small G1 assembly took 20 times longer with two threads).
/// The setting is global and cheap: every element loop calls this before it starts.
inline void keep_eigen_serial() { Eigen::setNbThreads(1); }

}  // namespace iga
