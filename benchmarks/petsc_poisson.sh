#!/usr/bin/env bash
# CHOLMOD against PETSc (CG + GAMG) on one level of cubic C2 B-spline Poisson on the unit square:
# errors, iterations, solve time and peak memory per rank (/usr/bin/time -v). Not a test: numbers
# for docs/parallel.md. Usage: benchmarks/petsc_poisson.sh BUILD_DIR ELEMENTS_PER_SIDE [RANKS] [--petsc-only]
# (1000 elements per side are 1 006 009 DOFs; CHOLMOD needs about 7 GB there; 2000 per side are
# 4 012 009 DOFs, beyond CHOLMOD on a 24 GB machine: --petsc-only skips it).
set -euo pipefail
build=${1:?build directory}
n=${2:?elements per side}
ranks=${3:-2}
petsc_only=${4:-}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

config() {  # config NAME SOLVER
  cat > "$work/$1.yaml" <<YAML
problem:
  pde: poisson
  exact: "sin(pi*x)*sin(2*pi*y)"
  boundary: {all: dirichlet}
domain: {type: rectangle, min: [0, 0], max: [1, 1]}
space: {type: bspline, degree: 3, regularity: 2, elements: [$n, $n]}
refinement: {levels: 1}
solver: $2
limits: {max_memory_gb: 1000}
output: {vtk: false, plot: false}
YAML
}

report() {  # report LABEL OUTPUT_DIR STDERR_FILE
  local row peak
  row=$(sed -n 2p "$2/convergence.csv" | cut -d, -f3-6,13,10,11)
  peak=$(grep "Maximum resident" "$3" | awk '{printf "%s%.2f GB", sep, $6/1e6; sep=", "}')
  local method
  method=$(grep -o "solved ([^)]*)" "$3" | head -1)
  echo "$1 | dofs,l2,h1,h2,t_assemble,t_solve,t_space: $row | $method | peak per rank: $peak"
}

config cholmod "{type: cholmod}"
config petsc "{type: petsc}"
if [[ $petsc_only != --petsc-only ]]; then
  /usr/bin/time -v "$build/iga-run" "$work/cholmod.yaml" -o "$work/out-cholmod" > /dev/null 2> "$work/cholmod.err"
  report "CHOLMOD" "$work/out-cholmod" "$work/cholmod.err"
fi
/usr/bin/time -v "$build/iga-run" "$work/petsc.yaml" -o "$work/out-petsc1" > /dev/null 2> "$work/petsc1.err"
report "PETSc np 1" "$work/out-petsc1" "$work/petsc1.err"
mpirun --allow-run-as-root --oversubscribe -np "$ranks" /usr/bin/time -v "$build/iga-run" "$work/petsc.yaml" \
  -o "$work/out-petsc$ranks" > /dev/null 2> "$work/petsc$ranks.err"
report "PETSc np $ranks" "$work/out-petsc$ranks" "$work/petsc$ranks.err"
