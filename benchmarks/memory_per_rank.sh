#!/usr/bin/env bash
# Peak memory per rank of one PETSc run on 1, 2 and 4 ranks (oversubscribed: memory only, not
# time), and the fit M(np) = R + D/np: R is what every rank holds whatever the rank count (the
# process itself, the replicated parts of the space), D what the ranks share. Not a test: numbers
# for docs/parallel.md. Usage:
#   benchmarks/memory_per_rank.sh BUILD_DIR CONFIG [LEVELS] [PETSc options...]
# LEVELS may list several ("7 8"): each is run at every rank count, and a fit over all the points
# of M = a + c·N + d·N/np separates what a process holds whatever the mesh (a) from what every
# rank holds per DOF (c) — a per-size fit books the process's constant part as bytes per DOF.
# RANKS="1 2" (default "1 2 4") chooses the rank counts: oversubscribed MUMPS runs crawl.
# REPEAT=3 (default 1) runs each rank count that often and takes the median peak: one run's peak
# moves by up to ±5 % with where the allocator's free blocks happen to lie.
# HEAP=1 measures each rank's peak heap (heaptrack, `apt-get install heaptrack`: what the program allocated, touched or not)
# instead of its resident set (what the system charged: touched pages, libraries, freed pages the
# allocator kept). The two differ by PETSc's preallocations that are never filled and by the
# allocator's kept pages; heaptrack makes the runs 2-3 times slower.
# RANKS="2 4" fits over parallel runs only: PETSc builds some structures only when a matrix has
# more than one rank (GAMG's aggregate graph, the off-diagonal blocks), of a size proportional to
# the rank's rows — divided, not replicated, but absent at np = 1, so a fit through np = 1 books
# them as replicated.
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
# heaptrack's peak, "1.30G", in bytes.
heap_peak() { heaptrack_print -f "$1" --print-peaks 0 --print-allocators 0 --print-temporary 0 --print-leaks 0 2> /dev/null |
  awk '/^peak heap memory consumption:/ { v = $5; u = substr(v, length(v)); v = substr(v, 1, length(v) - 1);
       f = (u == "K") ? 1e3 : (u == "M") ? 1e6 : (u == "G") ? 1e9 : 1; if (u ~ /[0-9]/) { v = $5; f = 1 } printf "%.0f\n", v * f }'; }
cat > "$work/traced" <<'SH'
#!/usr/bin/env bash
exec heaptrack -o "$HEAP_OUT.${OMPI_COMM_WORLD_RANK:-0}" "$@" > /dev/null
SH
chmod +x "$work/traced"
run=(/usr/bin/time -v)
[[ ${HEAP:-0} == 1 ]] && run=("$work/traced")
# Peak of the rank that peaks highest, in bytes, of a run whose output went to $1.err / $1.heap.*.
peak_of() {
  if [[ ${HEAP:-0} == 1 ]]; then
    for f in "$1".heap.*; do heap_peak "$f"; done | sort -n | tail -1
    rm -f "$1".heap.*
  else
    grep "Maximum resident" "$1.err" | awk '{ if ($6 > m) m = $6 } END { print m * 1024 }'
  fi
}
HEAP_OUT="$work/tiny.heap" "${run[@]}" "$build/iga-run" "$work/tiny.yaml" --quiet -o "$work/tiny" > /dev/null 2> "$work/tiny.err"
base=$(peak_of "$work/tiny")
declare -A peak dofs
ranks=(${RANKS:-1 2 4})
for level in $levels; do
  for np in "${ranks[@]}"; do
    runs=()
    for r in $(seq "${REPEAT:-1}"); do
      HEAP_OUT="$work/run$np.heap" mpirun --allow-run-as-root --oversubscribe -x HEAP_OUT -np "$np" "${run[@]}" \
        "$build/iga-run" "$work/run.yaml" --levels "$level" --quiet -o "$work/out$np" "$@" > /dev/null 2> "$work/run$np.err"
      runs+=("$(peak_of "$work/run$np")")
    done
    peak[$level,$np]=$(printf '%s\n' "${runs[@]}" | sort -n | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }')
    echo "levels=$level np=$np peaks per run (largest rank): ${runs[*]}" >&2
  done
  dofs[$level]=$(tail -1 "$work/out${ranks[0]}/convergence.csv" | cut -d, -f3)
done
points=""
for level in $levels; do
  for np in "${ranks[@]}"; do points+=" ${dofs[$level]}:$np:${peak[$level,$np]}"; done
done
python3 - "$base" "${HEAP:-0}" $points <<'PY'
import sys


def lstsq(rows, ys):
    """Least squares by the normal equations, columns scaled to 1 (a few unknowns)."""
    k = len(rows[0])
    scale = [max(abs(r[j]) for r in rows) or 1.0 for j in range(k)]
    A = [[r[j] / scale[j] for j in range(k)] for r in rows]
    N = [[sum(a[i] * a[j] for a in A) for j in range(k)] + [sum(a[i] * y for a, y in zip(A, ys))] for i in range(k)]
    for i in range(k):  # Gauss-Jordan with partial pivoting
        p = max(range(i, k), key=lambda r: abs(N[r][i]))
        N[i], N[p] = N[p], N[i]
        for r in range(k):
            if r != i:
                f = N[r][i] / N[i][i]
                N[r] = [x - f * y for x, y in zip(N[r], N[i])]
    return [N[i][k] / N[i][i] / scale[i] for i in range(k)]


base, heap = float(sys.argv[1]), sys.argv[2] == "1"
points = [(int(a), int(b), float(c)) for a, b, c in (p.split(":") for p in sys.argv[3:])]
kind = "heap" if heap else "resident"
# Per size, least squares over the rank counts of M = R + D/np (one rank count: the peaks only).
for dofs in sorted({d for d, _, _ in points}):
    pairs = [(n, m) for d, n, m in points if d == dofs]
    if len(pairs) < 2:
        print(f"dofs {dofs}: {kind} peak per rank " + ", ".join(f"np={n} {m/1e9:.3f} GB" for n, m in pairs))
        continue
    R, D = lstsq([[1.0, 1.0 / n] for n, _ in pairs], [m for _, m in pairs])
    peaks = ", ".join(f"np={n} {m/1e9:.3f} GB" for n, m in pairs)
    print(f"dofs {dofs}: {kind} peak per rank {peaks}; "
          f"fit R = {R/1e6:.0f} MB, of which the process alone {base/1e6:.0f} MB: replicated "
          f"{(R-base)/1e6:.0f} MB ({(R-base)/dofs:.0f} B/DOF); shared D = {D/1e9:.3f} GB ({D/dofs:.0f} B/DOF)")
# Over several sizes, M = a + c N + d N/np: a is what a process holds whatever the mesh (libraries,
# MPI's buffers, tables independent of the mesh), c what every rank holds per DOF of the whole
# problem (the replicated part proper), d what the ranks share per DOF.
if len({d for d, _, _ in points}) > 1 and len({n for _, n, _ in points}) > 1:
    a, c, d = lstsq([[1.0, N, N / n] for N, n, _ in points], [m for _, _, m in points])
    worst = max(abs(m - (a + c * N + d * N / n)) for N, n, m in points)
    print(f"over the sizes: M = a + c N + d N/np with a = {a/1e6:.0f} MB per process, "
          f"c = {c:.0f} B/DOF replicated, d = {d:.0f} B/DOF divided (largest misfit {worst/1e6:.0f} MB)")
PY
