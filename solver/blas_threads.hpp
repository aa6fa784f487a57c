#pragma once
/// @file
/// Threads of the BLAS under CHOLMOD's supernodal factorization. Debian's default BLAS, OpenBLAS,
/// keeps its own pool of threads, and after every call its idle threads spin (sched_yield) for
/// about 2^28 cycles: on a small system that spinning takes more from the phases after the
/// factorization than the second thread saved in it (a 5-level G1 study: 0.50 s → 0.41 s with one
/// BLAS thread), and it ignored --threads.

namespace iga {

/// Below this many unknowns the factorization runs its BLAS on one thread (measured on two cores:
/// one thread is faster at 5e4 unknowns, two are 15-20 % faster from 1.4e5).
inline constexpr int kParallelBlasUnknowns = 80000;

/// One BLAS thread for a factorization of fewer than kParallelBlasUnknowns unknowns, else as many
/// as OpenMP uses. No effect when the user set OPENBLAS_NUM_THREADS, or with a BLAS that has no
/// openblas_set_num_threads (looked up at run time: whichever BLAS Debian's alternatives select).
void set_blas_threads_for(int unknowns);
/// `threads` BLAS threads (MUMPS's dense kernels under PETSc too), with the same exceptions.
void set_blas_threads(int threads);

}  // namespace iga
