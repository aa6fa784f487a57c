#!/usr/bin/env bash
# Install every Debian package, configure and build everything (Release) in build/: iga-run, the
# tests, examples, benchmarks and the Python module, with PETSc (README command 2, scripts/test.sh).
# Idempotent: a second run installs nothing and rebuilds only what changed.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
# On explicitly: a build/ that scripts/quickstart.sh configured first has them off.
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=ON -DIGA_PYTHON=ON -DIGA_WITH_PETSC=ON \
  > build-configure.log 2>&1 || { cat build-configure.log; exit 1; }
rm -f build-configure.log
cmake --build build -j "$(nproc)"
