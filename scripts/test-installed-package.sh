#!/usr/bin/env bash
# The installed package, as another project sees it (the ctest `installed_package`):
#   scripts/test-installed-package.sh BUILD_DIR SCRATCH_DIR
# installs BUILD_DIR into SCRATCH_DIR/prefix, builds examples/ there as a separate CMake project
# against find_package(iga_run), runs embed_clamped_plate, and, when the Python module was built,
# runs a study through the installed `iga_run` package with Debian's Python, and, when PETSc was
# built in, runs the installed iga-run on a PETSc config (it must find its plugin in lib/iga-run/).
set -euo pipefail
build=$(realpath "$1")
scratch=$2
source_dir=$(realpath "$(dirname "$0")/..")
rm -rf "$scratch"
mkdir -p "$scratch"
scratch=$(realpath "$scratch")
prefix=$scratch/prefix

cmake --install "$build" --prefix "$prefix" > "$scratch/install.log"
echo "installed into $prefix"

cmake -S "$source_dir/examples" -B "$scratch/examples" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release \
  > "$scratch/examples-configure.log" || { cat "$scratch/examples-configure.log"; exit 1; }
cmake --build "$scratch/examples" -j 2 > "$scratch/examples-build.log" || { cat "$scratch/examples-build.log"; exit 1; }
"$scratch/examples/embed_clamped_plate"

if [ -f "$prefix/lib/iga-run/iga-run-petsc.so" ]; then
  "$prefix/bin/iga-run" -q "$source_dir/configs/bspline-poisson-petsc.yaml" --levels 1 -o "$scratch/petsc-run"
  grep -q '"solver": "petsc' "$scratch/petsc-run/summary.json"
  echo "installed iga-run: solver.type petsc through $prefix/lib/iga-run/iga-run-petsc.so"
fi

python_dir=$prefix/lib/python3/dist-packages
if [ -d "$python_dir/iga_run" ]; then
  PYTHONPATH="$python_dir" /usr/bin/python3 - <<'PY'
import iga_run
study = iga_run.run({
    "problem": {"pde": "poisson", "exact": "sin(pi*x)*sin(pi*y)", "boundary": {"all": "dirichlet"}},
    "domain": {"type": "rectangle", "min": [0, 0], "max": [1, 1]},
    "space": {"type": "bspline", "degree": 2, "elements": [4, 4]},
    "refinement": {"levels": 3},
})
print("python: iga_run", iga_run.__version__, "from", iga_run.__file__)
for row in study.levels:
    print("  level %d  dofs %4d  L2 %.4e  rate %s" % (row["level"], row["dofs"], row["l2"], row["rate_l2"]))
print("  u_h(0.5, 0.5) = %.6f (exact 1)" % study.solution([0.5, 0.5]))
PY
fi
