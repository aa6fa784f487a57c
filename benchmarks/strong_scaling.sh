#!/usr/bin/env bash
# Strong scaling of one PETSc run from 1 to 2 ranks (or to RANKS): wall time per phase of the
# finest level (convergence.csv) and of the whole process, each the median of REPEAT runs. Only
# meaningful on an idle machine with at least RANKS cores. Not a test: numbers for docs/parallel.md.
#   benchmarks/strong_scaling.sh BUILD_DIR CONFIG [LEVELS] [REPEAT] [RANKS] [PETSc options...]
set -euo pipefail
build=${1:?build directory}
config=${2:?config}
levels=${3:-1}
repeat=${4:-3}
ranks=${5:-2}
shift 5 || shift $#
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
grep -v -E '^(solver|output|limits):' "$config" > "$work/run.yaml"
solver=$(grep -E '^solver:' "$config" | sed 's/^solver: *//' || true)
[[ $solver == *petsc* ]] || solver="{type: petsc}"
cat >> "$work/run.yaml" <<YAML
solver: $solver
output: {vtk: false, plot: false}
limits: {max_memory_gb: 1000}
YAML
for np in 1 "$ranks"; do
  for r in $(seq "$repeat"); do
    start=$(date +%s.%N)
    mpirun --allow-run-as-root -np "$np" "$build/iga-run" "$work/run.yaml" --levels "$levels" --quiet \
      -o "$work/out$np-$r" "$@" > /dev/null 2> "$work/err$np-$r"
    end=$(date +%s.%N)
    echo "$np $(echo "$end - $start" | bc) $(tail -1 "$work/out$np-$r/convergence.csv")" >> "$work/rows"
  done
done
python3 - "$work/rows" "$(head -1 "$work/out1-1/convergence.csv")" <<'PY'
import statistics, sys
header = sys.argv[2].split(",")
col = {name: header.index(name) for name in ("dofs", "t_space", "t_assemble", "t_solve", "t_errors")}
runs = {}
for line in open(sys.argv[1]):
    np_, wall, csv = line.split(" ", 2)
    cells = csv.strip().split(",")
    runs.setdefault(int(np_), []).append([float(wall)] + [float(cells[col[k]]) for k in ("t_space", "t_assemble", "t_solve", "t_errors")])
names = ["whole run", "space", "assembly + load", "solve", "errors"]
med = {n: [statistics.median(r[i] for r in rows) for i in range(5)] for n, rows in runs.items()}
first, last = min(med), max(med)
print(f"| phase (DOFs {cells[col['dofs']]}) | np = {first} | np = {last} | speed-up |")
print("|---|---|---|---|")
for i, name in enumerate(names):
    a, b = med[first][i], med[last][i]
    print(f"| {name} | {a:.2f} s | {b:.2f} s | {a / b:.2f} |" if b > 0 else f"| {name} | {a:.2f} s | {b:.2f} s | – |")
PY
