#!/usr/bin/env bash
# Strong scaling of one PETSc run from 1 to 2 ranks (or to RANKS): wall time per phase of the
# finest level (convergence.csv) and of the whole process, and the peak resident memory per rank
# (/usr/bin/time -v), each the median of REPEAT runs. Only meaningful on an idle machine with at
# least RANKS cores. Not a test: numbers for docs/parallel.md.
#   benchmarks/strong_scaling.sh BUILD_DIR[,BUILD_DIR2...] CONFIG [LEVELS] [REPEAT] [RANKS] [PETSc options...]
# With several build directories (before and after a change) the runs alternate between them, so
# that a machine whose load drifts affects both alike; one table per build.
set -euo pipefail
build_list=${1:?build directory}
IFS=, read -r -a builds <<< "$build_list"
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
for r in $(seq "$repeat"); do
  for b in "${!builds[@]}"; do
    for np in 1 "$ranks"; do
      out="$work/out$b-$np-$r"
      start=$(date +%s.%N)
      mpirun --allow-run-as-root -np "$np" /usr/bin/time -v "${builds[$b]}/iga-run" "$work/run.yaml" \
        --levels "$levels" --quiet -o "$out" "$@" > /dev/null 2> "$out.err"
      end=$(date +%s.%N)
      peak=$(grep "Maximum resident" "$out.err" | awk '{print $6}' | sort -n | tail -1)
      echo "$b $np $(echo "$end - $start" | bc) $peak $(tail -1 "$out/convergence.csv")" >> "$work/rows"
    done
  done
done
python3 - "$work/rows" "$(head -1 "$work/out0-1-1/convergence.csv")" "$build_list" <<'PY'
import statistics, sys
header = sys.argv[2].split(",")
builds = sys.argv[3].split(",")
phases = ("t_space", "t_assemble", "t_solve", "t_errors")
col = {name: header.index(name) for name in ("dofs",) + phases}
runs = {}
for line in open(sys.argv[1]):
    b, np_, wall, peak, csv = line.split(" ", 4)
    cells = csv.strip().split(",")
    t = [float(cells[col[k]]) for k in phases]
    rest = float(wall) - sum(t)  # start-up, partition, data checks, output, exit
    runs.setdefault(int(b), {}).setdefault(int(np_), []).append([float(wall)] + t + [rest, float(peak) / 1024])
names = ["whole run", "space", "assembly + load", "solve", "errors",
         "the rest (start-up, partition, data checks, coarser levels, exit)",
         "peak memory per rank (MB)"]
for b, by_np in sorted(runs.items()):
    med = {n: [statistics.median(r[i] for r in rows) for i in range(len(names))] for n, rows in by_np.items()}
    first, last = min(med), max(med)
    print(f"\n{builds[b]}\n| phase (DOFs {cells[col['dofs']]}) | np = {first} | np = {last} | ideal | loss | speed-up |")
    print("|---|---|---|---|---|---|")
    for i, name in enumerate(names):
        a, c = med[first][i], med[last][i]
        if i == len(names) - 1:
            print(f"| {name} | {a:.0f} | {c:.0f} | {a / last:.0f} | | |")
            continue
        ideal = a * first / last
        print(f"| {name} | {a:.2f} s | {c:.2f} s | {ideal:.2f} s | {c - ideal:.2f} s | "
              + (f"{a / c:.2f} |" if c > 0 else "– |"))
PY
