#!/usr/bin/env bash
# The cost of the first 20 eigenpairs against one linear solve of the same matrix (issue 24: at
# most 5x at >= 1e5 DOFs): cubic C2 B-splines on 320 x 320 elements (104329 DOFs, 103041 free),
# the Dirichlet Laplacian on the unit square. Runs, alternately and ROUNDS times each,
#   serial eigen (Spectra + CHOLMOD), SLEPc eigen (solver.type: petsc, 1 rank, MUMPS Cholesky),
#   the CHOLMOD linear solve and the PETSc MUMPS linear solve (ksp: preonly, pc: mumps, with its refinement steps) of
#   the same operator (exact sin(pi x) sin(pi y)),
# and prints the `solve` time of each run (summary.json, wall clock), the CPU time of the whole
# process (assembly included) and the load average before it. Not a test: numbers for
# docs/eigen.md; compare runs made side by side only, on a machine that is not saturated (under
# heavy oversubscription neither wall nor CPU times measured the work: docs/eigen.md).
# Usage: benchmarks/slepc_eigen_cost.sh BUILD_DIR [ROUNDS] [ELEMENTS_PER_SIDE]
# SLEPC_OPTIONS (e.g. "-eps_ncv 60") reach the SLEPc run only, as its PETSC_OPTIONS. RUNS lists
# the runs of a round (default: the four above); `eigen-slepc-purify` is the SLEPc run with
# -eps_purify 1, how it ran before purification was switched off (docs/eigen.md).
set -euo pipefail
build=${1:?build directory}
rounds=${2:-2}
n=${3:-320}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

config() {  # config NAME PROBLEM_EXTRA SOLVER
  cat > "$work/$1.yaml" <<YAML
problem:
  pde: poisson
  boundary: {all: dirichlet}
  $2
domain: {type: rectangle, min: [0, 0], max: [1, 1]}
space: {type: bspline, degree: 3, elements: [$n, $n]}
refinement: {levels: 1}
solver: $3
output: {vtk: false, plot: false}
YAML
}

config eigen-serial 'eigen: {count: 20, exact_eigenvalues: "pi^2*(m^2 + n^2)"}' '{type: cholmod}'
config eigen-slepc 'eigen: {count: 20, exact_eigenvalues: "pi^2*(m^2 + n^2)"}' '{type: petsc}'
config linear-cholmod 'exact: "sin(pi*x)*sin(pi*y)"' '{type: cholmod}'
config linear-mumps 'exact: "sin(pi*x)*sin(pi*y)"' '{type: petsc, ksp: preonly, pc: mumps}'

run() {  # run NAME ROUND
  local load out=$work/out-$1-$2
  load=$(cut -d' ' -f1 /proc/loadavg)
  local options= yaml=$1
  [[ $1 == eigen-slepc* ]] && options=${SLEPC_OPTIONS:-}
  [[ $1 == eigen-slepc-purify ]] && yaml=eigen-slepc options="$options -eps_purify 1"
  PETSC_OPTIONS=$options /usr/bin/time -f "%U %S" -o "$out.time" "$build/iga-run" "$work/$yaml.yaml" -o "$out" \
    > /dev/null 2> "$out.err" || { cat "$out.err"; exit 1; }
  python3 - "$1" "$2" "$load" "$out" <<'PY'
import json, sys
name, rnd, load, out = sys.argv[1:]
summary = json.load(open(out + "/summary.json"))
level = summary["levels"][-1]
t = level["timings"]
user, system = map(float, open(out + ".time").read().split()[-2:])
cpu, wall = user + system, summary["total_seconds"]
# The CPU time spent in the solve, estimated as the solve's share of the wall time times the
# process's CPU time.
print(f"{name:18s} round {rnd}  load {load:>5s}  dofs {level['dofs']}  solve {t['solve']:7.2f} s  "
      f"assemble {t['assemble']:7.2f} s  wall {wall:7.2f} s  process CPU {cpu:6.2f} s  "
      f"solve CPU ~ {cpu * t['solve'] / wall:6.2f} s")
PY
  grep -o "eigensolve: [0-9]* \(solves\|restarts\)[^,]*, [^)]*)" "$out.err" | sed 's/^/    /' || true
}

for round in $(seq 1 "$rounds"); do
  for name in ${RUNS:-eigen-serial linear-cholmod eigen-slepc linear-mumps}; do run "$name" "$round"; done
done
