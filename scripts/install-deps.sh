#!/usr/bin/env bash
# Installs the Debian 12 packages iga-run builds against (see ../shared/notes/debian-stack.md).
#   scripts/install-deps.sh run   what building and running iga-run needs (README command 1, quickstart.sh)
#   scripts/install-deps.sh       all of it: also the tests, benchmarks, Python module, PETSc, the
#                                 render test and the fuzzers (command 2, test.sh, CI, fuzz.sh)
# Idempotent: apt-get skips what is already installed; the package index is refreshed only when
# a package is missing, so a second run costs a second or two.
set -euo pipefail

# Group 1: building and running iga-run (PETSc is optional in CMake: quickstart.sh builds without it).
run_packages=(
  build-essential cmake pkg-config ninja-build
  libeigen3-dev libsuitesparse-dev libyaml-cpp-dev libvtk9-dev
  libginac-dev libmuparser-dev libplplot-dev plplot-driver-cairo
  libcli11-dev nlohmann-json3-dev
  libspectra-dev         # Spectra, header-only Lanczos/Arnoldi: the eigensolver of problem.eigen (solver/eigen_solver.cpp)
  libgmsh-dev            # Gmsh SDK: reading .msh, meshing .geo domains and polygons (mesh/)
  libseccomp-dev         # system-call filter of the Gmsh worker process (mesh/worker_sandbox.cpp)
  libtinyxml2-dev        # G+Smo XML geometry files (mesh/gismo_xml.cpp)
  libopenblas0-pthread   # optimized BLAS/LAPACK for CHOLMOD's supernodal factorization (reference BLAS is ~5x slower)
)

# Group 2: everything else command 2 and CI build and run.
test_packages=(
  libgtest-dev libbenchmark-dev              # the tests (tests/) and the benchmarks (benchmarks/)
  pybind11-dev python3-dev python3-numpy   # the Python module iga_run (python/), for Debian's /usr/bin/python3
  python3-scipy python3-matplotlib          # its tests (Matrix Market read-back) and python/examples/
  petsc-dev              # PETSc with OpenMPI, MUMPS and hypre: solver.type petsc, mpirun -np N (solver/petsc_*)
  libslepc-real-dev      # SLEPc 3.18 (matches PETSc 3.18): eigenproblems under solver.type petsc (solver/slepc_eigen_backend.cpp)
  xvfb xauth             # an X server for ctest vtk_render (Debian's VTK renders off-screen only through X)
  python3-vtk9           # scripts/render-gallery.py: VTK's Python bindings (docs/gallery.md, ctest render_gallery)
  clang libclang-rt-14-dev libomp-14-dev   # scripts/fuzz.sh: libFuzzer and the sanitizers for clang, OpenMP for clang
)

case "${1:-all}" in
  run) packages=("${run_packages[@]}") ;;
  all) packages=("${run_packages[@]}" "${test_packages[@]}") ;;
  *) echo "usage: $0 [run|all]" >&2; exit 2 ;;
esac

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

sudo_cmd=""
[ "$(id -u)" -eq 0 ] || sudo_cmd="sudo"
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$sudo_cmd apt-get update -qq
# --force-unsafe-io: dpkg skips its fsync per unpacked file (a fresh Debian 12 chroot: 2 min 50 s
# instead of 4 min 54 s for command 1's 600 packages); the price: a power loss during the install
# could leave an unpacked file half-written.
$sudo_cmd apt-get install -y -qq --no-install-recommends -o Dpkg::Options::=--force-unsafe-io "${missing[@]}"
