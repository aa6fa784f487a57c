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
# A rank's part is more than N/np unknowns: the rows it owns and a layer of ghosts (and the
# boundary band), a layer that grows like the cut, not like N/np — the fits above book it as
# replicated. Where the run names its part (PETSc on several ranks: "unknowns of this rank's part:
# U, rows it owns: R"), a last fit takes rank 0's peak against rank 0's part over three sizes or
# more at two rank counts or more, M0 = a + c·N + d·R0 + g·(U0 − R0): c is then what a rank holds per DOF beyond its rows and
# its ghosts.
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
# Each rank measured into a file of its own: $PEAK_OUT.<rank>.
cat > "$work/measured" <<'SH'
#!/usr/bin/env bash
rank=${OMPI_COMM_WORLD_RANK:-0}
[[ ${HEAP:-0} == 1 ]] && exec heaptrack -o "$PEAK_OUT.$rank" "$@" > /dev/null
exec /usr/bin/time -f %M -o "$PEAK_OUT.$rank" "$@"
SH
chmod +x "$work/measured"
# One rank's peak in bytes, from its file.
rank_peak() {
  if [[ ${HEAP:-0} == 1 ]]; then heap_peak "$1"; else echo $(($(cat "$1") * 1024)); fi
}
# "LARGEST RANK0": the peak of the rank that peaks highest and rank 0's, in bytes, of a run
# measured into $1.*.
peaks_of() {
  local f largest=0 p first=("$1".0*)  # rank 0's file: .0, or .0.zst from heaptrack
  for f in "$1".*; do
    p=$(rank_peak "$f")
    ((p > largest)) && largest=$p
  done
  echo "$largest $(rank_peak "${first[0]}")"
  rm -f "$1".*
}
export HEAP
PEAK_OUT="$work/tiny.peak" "$work/measured" "$build/iga-run" "$work/tiny.yaml" --quiet -o "$work/tiny" > /dev/null 2> "$work/tiny.err"
read -r base _ < <(peaks_of "$work/tiny.peak")
median() { printf '%s\n' "$@" | sort -n | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }
declare -A peak peak0 part rows dofs
ranks=(${RANKS:-1 2 4})
for level in $levels; do
  for np in "${ranks[@]}"; do
    runs=() runs0=()
    for r in $(seq "${REPEAT:-1}"); do
      # Not --quiet: rank 0 names the size of its part on standard error.
      PEAK_OUT="$work/run$np.peak" mpirun --allow-run-as-root --oversubscribe -x PEAK_OUT -np "$np" "$work/measured" \
        "$build/iga-run" "$work/run.yaml" --levels "$level" -o "$work/out$np" "$@" > /dev/null 2> "$work/run$np.err"
      read -r largest first < <(peaks_of "$work/run$np.peak")
      runs+=("$largest") runs0+=("$first")
    done
    peak[$level,$np]=$(median "${runs[@]}")
    peak0[$level,$np]=$(median "${runs0[@]}")
    # The finest level's line: "unknowns of this rank's part: 408956, rows it owns: 392695 of ...".
    line=$(grep -o "unknowns of this rank's part: [0-9]*, rows it owns: [0-9]*" "$work/run$np.err" | tail -1 || true)
    part[$level,$np]=$(sed -n 's/.*part: \([0-9]*\),.*/\1/p' <<< "$line")
    rows[$level,$np]=$(sed -n 's/.*owns: \([0-9]*\)$/\1/p' <<< "$line")
    echo "levels=$level np=$np peaks per run (largest rank): ${runs[*]}; rank 0: ${runs0[*]}," \
         "its part ${part[$level,$np]:-not named} unknowns, ${rows[$level,$np]:-?} rows" >&2
  done
  dofs[$level]=$(tail -1 "$work/out${ranks[0]}/convergence.csv" | cut -d, -f3)
done
points=""
for level in $levels; do
  for np in "${ranks[@]}"; do
    points+=" ${dofs[$level]}:$np:${peak[$level,$np]}:${part[$level,$np]:-0}:${rows[$level,$np]:-0}:${peak0[$level,$np]}"
  done
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
rows = [p.split(":") for p in sys.argv[3:]]
points = [(int(r[0]), int(r[1]), float(r[2])) for r in rows]
# Rank 0: (DOFs, its part's unknowns, the rows it owns, its peak); 0 where the run did not name them.
firsts = [(int(r[0]), int(r[3]), int(r[4]), float(r[5])) for r in rows]
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
# Rank 0 against its own part: M0 = a + c N + d R0 + g G0, G0 = U0 - R0 its ghosts (and band).
# Only the runs that name their part (one rank names none: its part is the whole); four unknowns
# want three sizes at two rank counts or more, so that the fit has points to spare.
named = [(N, U, R, m) for (N, U, R, m), (_, n, _) in zip(firsts, points) if U > 0 and R > 0]
counts = {n for (_, U, R, _), (_, n, _) in zip(firsts, points) if U > 0 and R > 0}
if len({N for N, _, _, _ in named}) > 2 and len(counts) > 1:
    A = [[1.0, N, R, U - R] for N, U, R, _ in named]
    a, c, d, g = lstsq(A, [m for _, _, _, m in named])
    worst = max(abs(m - (a + c * N + d * R + g * (U - R))) for N, U, R, m in named)
    parts = ", ".join(f"{R}+{U - R}" for N, U, R, _ in named)
    print(f"rank 0 against its part (rows + ghosts: {parts}): M0 = a + c N + d R0 + g G0 with "
          f"a = {a/1e6:.0f} MB, c = {c:.0f} B/DOF replicated, d = {d:.0f} B per row, g = {g:.0f} B per ghost "
          f"(largest misfit {worst/1e6:.0f} MB)")
PY
