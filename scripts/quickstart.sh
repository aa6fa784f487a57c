#!/usr/bin/env bash
# README command 1: install what iga-run needs, build only iga-run (Release, in build/), and run the
# default example (configs/quickstart.yaml); each step's time is printed. The tests, the Python
# module, PETSc and the fuzzers are command 2's (scripts/test.sh), which builds the rest in the same
# build/ folder. Idempotent: a second run installs nothing and rebuilds only what changed.
# Arguments go to iga-run (e.g. --levels 3).
set -euo pipefail
cd "$(dirname "$0")/.."

times=()
started=$(date +%s%N)
step() {  # step NAME COMMAND...: run it, remember how long it took
  local name=$1 start end
  shift
  start=$(date +%s%N)
  "$@"
  end=$(date +%s%N)
  local ms=$(((end - start) / 1000000))
  times+=("$(printf '%-20s %5d.%01d s' "$name" $((ms / 1000)) $((ms % 1000 / 100)))")
}

configure() {
  # A first configure leaves out what command 2 adds (tests, Python module, PETSc) and compiles each
  # layer in batches (a unity build: a third less compiler time from scratch, see
  # docs/developing.md); an existing build/ keeps its settings (command 2 may have turned them on).
  # Ninja (installed by command 1) keeps both cores busy across the layers, where Make waits for
  # each layer's longest batch (a fresh 2-core chroot: 214 s against 240 s).
  local first=()
  [ -f build/CMakeCache.txt ] ||
    first=(-G Ninja -DBUILD_TESTING=OFF -DIGA_PYTHON=OFF -DIGA_WITH_PETSC=OFF -DIGA_UNITY_BUILD=ON)
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release "${first[@]}" > build-configure.log 2>&1 ||
    { cat build-configure.log; exit 1; }
  rm -f build-configure.log
}

step "packages (apt)" bash scripts/install-deps.sh run
step "configure (cmake)" configure
step "build iga-run" cmake --build build -j "$(nproc)" --target iga-run
step "run the example" ./build/iga-run configs/quickstart.yaml "$@"

total_ms=$((($(date +%s%N) - started) / 1000000))
times+=("$(printf '%-20s %5d.%01d s' "total" $((total_ms / 1000)) $((total_ms % 1000 / 100)))")
echo
echo "quickstart: time per step"
printf '  %s\n' "${times[@]}"
