#!/usr/bin/env bash
# Sanitizer run: builds everything Debug with AddressSanitizer + UndefinedBehaviorSanitizer (and
# Eigen's and libstdc++'s assertions) in build-sanitize/, then runs the whole ctest there.
# Any sanitizer report ends the process with an error, so it fails the test that caused it.
#   scripts/sanitize.sh [ctest arguments...]      e.g. scripts/sanitize.sh -R Ws4
# JOBS sets the build and test parallelism (default: all cores).
# The inhomogeneous patch test runs its studies only to level 2 in this build (the 1e5-DOF levels
# take many minutes under ASan); IGA_PATCH_TEST_MAX_LEVEL=6 runs them all.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
jobs=${JOBS:-$(nproc)}

# halt_on_error: the first report ends the process (exit code 1 for ASan, abort for UBSan).
export ASAN_OPTIONS="detect_leaks=1:halt_on_error=1:check_initialization_order=1:strict_init_order=1:detect_stack_use_after_return=1:${ASAN_OPTIONS:-}"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:${UBSAN_OPTIONS:-}"
export LSAN_OPTIONS="suppressions=${root}/scripts/sanitize-leaks.supp:print_suppressions=0:${LSAN_OPTIONS:-}"

cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=Debug -DIGA_SANITIZE=ON > build-sanitize-configure.log 2>&1 \
  || { cat build-sanitize-configure.log; exit 1; }
rm -f build-sanitize-configure.log
cmake --build build-sanitize -j "$jobs"
cd build-sanitize
# The tests that start MPI (PETSc solves, mpirun) need LeakSanitizer's full stacks: Open MPI's own
# allocations are suppressed by the functions they come from (sanitize-leaks.supp), which the fast
# unwinder does not reach. The slow unwinder costs every allocation, so only those tests get it.
mpi_tests='petsc|Petsc|PETSc|slepc|Slepc|SLEPc|TwoRanks|Mpi|mpi'
slow_unwind="ASAN_OPTIONS=${ASAN_OPTIONS}:fast_unwind_on_malloc=0"
if [ $# -gt 0 ]; then  # a selection of the caller's: one pass, full stacks
  env "$slow_unwind" ctest --output-on-failure -j "$jobs" "$@"
else
  status=0
  ctest --output-on-failure -j "$jobs" -E "$mpi_tests" || status=$?
  env "$slow_unwind" ctest --output-on-failure -j "$jobs" -R "$mpi_tests" || status=$?
  exit $status
fi
