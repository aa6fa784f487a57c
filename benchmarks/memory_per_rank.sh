#!/usr/bin/env bash
# Peak memory per rank of one PETSc run on 1, 2 and 4 ranks (oversubscribed: memory only, not
# time), and the fit M(np) = R + D/np: R is what every rank holds whatever the rank count (the
# process itself, the replicated parts of the space), D what the ranks share. Not a test: numbers
# for docs/parallel.md. Usage:
#   benchmarks/memory_per_rank.sh BUILD_DIR CONFIG [LEVELS] [PETSc options...]
# RANKS="1 2" (default "1 2 4") chooses the rank counts: oversubscribed MUMPS runs crawl.
# REPEAT=3 (default 1) runs each rank count that often and takes the median peak: one run's peak
# moves by up to ±5 % with where the allocator's free blocks happen to lie.
# The config runs as given except solver.type (petsc), output (no VTK, no plot) and limits.
set -euo pipefail
build=${1:?build directory}
config=${2:?config}
levels=${3:-1}
shift 3 || shift $#
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
grep -v -E '^(solver|output|limits):' "$config" > "$work/run.yaml"
cat >> "$work/run.yaml" <<YAML
solver: {type: petsc}
output: {vtk: false, plot: false}
limits: {max_memory_gb: 1000}
YAML
# The process alone (libraries, MPI, PETSc): a 49-DOF run.
cat > "$work/tiny.yaml" <<YAML
problem: {pde: poisson, exact: "x*y", boundary: {all: dirichlet}}
domain: {type: rectangle, min: [0, 0], max: [1, 1]}
space: {type: bspline, degree: 3, elements: [4, 4]}
refinement: {levels: 1}
solver: {type: petsc}
output: {vtk: false, plot: false}
YAML
/usr/bin/time -v "$build/iga-run" "$work/tiny.yaml" --quiet -o "$work/tiny" > /dev/null 2> "$work/tiny.err"
base=$(grep "Maximum resident" "$work/tiny.err" | awk '{ print $6 * 1024 }')
declare -A peak
ranks=(${RANKS:-1 2 4})
for np in "${ranks[@]}"; do
  runs=()
  for r in $(seq "${REPEAT:-1}"); do
    mpirun --allow-run-as-root --oversubscribe -np "$np" /usr/bin/time -v "$build/iga-run" "$work/run.yaml" \
      --levels "$levels" --quiet -o "$work/out$np" "$@" > /dev/null 2> "$work/err$np"
    runs+=("$(grep "Maximum resident" "$work/err$np" | awk '{ if ($6 > m) m = $6 } END { print m * 1024 }')")
  done
  peak[$np]=$(printf '%s\n' "${runs[@]}" | sort -n | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }')
  echo "np=$np peaks per run (largest rank): ${runs[*]}" >&2
done
dofs=$(tail -1 "$work/out1/convergence.csv" | cut -d, -f3)
points=""
for np in "${ranks[@]}"; do points+=" $np:${peak[$np]}"; done
python3 - "$dofs" "$base" $points <<'PY'
import sys
dofs, base = int(sys.argv[1]), float(sys.argv[2])
pairs = [(int(a), float(b)) for a, b in (p.split(":") for p in sys.argv[3:])]
# Least squares over the points of M = R + D/np (x = 1/np).
xs, ys = [1 / n for n, _ in pairs], [m for _, m in pairs]
xm, ym = sum(xs) / len(xs), sum(ys) / len(ys)
D = sum((x - xm) * (y - ym) for x, y in zip(xs, ys)) / sum((x - xm) ** 2 for x in xs)
R = ym - D * xm
peaks = ", ".join(f"np={n} {m/1e9:.3f} GB" for n, m in pairs)
print(f"dofs {dofs}: peak per rank {peaks}; "
      f"fit R = {R/1e6:.0f} MB, of which the process alone {base/1e6:.0f} MB: replicated "
      f"{(R-base)/1e6:.0f} MB ({(R-base)/dofs:.0f} B/DOF); shared D = {D/1e9:.3f} GB ({D/dofs:.0f} B/DOF)")
PY
