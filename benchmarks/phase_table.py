#!/usr/bin/env python3
"""Phase times of iga-run at >= 1e5 DOFs, one space per row, from each run's summary.json.

Runs `iga-run` on the configs in benchmarks/configs/ and prints a Markdown table: space build,
assembly + load, factorize + solve, error norms, the rest of the process (VTK, tables, start-up)
and the ratio (whole wall time - factorize and solve) / (factorize and solve), the number the
project wants at most 0.3. Speed is measured here, never asserted in tests.

  benchmarks/phase_table.py --binary build/iga-run --threads 2 [--repeat 3] [--only ws4-plate]
  benchmarks/phase_table.py --binary before/iga-run --binary build/iga-run   # side by side

Wall time on a shared machine is noisy: the load average before and after is printed, and the
process's CPU time (user + system of the child) is reported next to its wall time.
"""
import argparse
import json
import os
import resource
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
CASES = [
    ("bspline p=3 plate", "bspline-p3-plate.yaml"),
    ("g1 k=5 plate", "g1-k5-plate.yaml"),
    ("ws4 Poisson", "ws4-poisson.yaml"),
    ("ws4 plate", "ws4-plate.yaml"),
    ("tmesh C1 n=3 plate", "tmesh-c1-plate.yaml"),
    ("g1 k=6 small study", "g1-k6-small.yaml"),
    ("surface p=3 sphere (LB)", "surface-p3-sphere.yaml"),
    ("g1_4split k=5 cube (LB)", "g1_4split-k5-cube.yaml"),
]


def run_once(binary, config, threads):
    env = dict(os.environ, OMP_NUM_THREADS=str(threads))
    with tempfile.TemporaryDirectory(prefix="iga-bench-") as out:
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        start = time.perf_counter()
        subprocess.run([binary, "-q", "-o", out, config], env=env, check=True,
                       stdout=subprocess.DEVNULL)
        wall = time.perf_counter() - start
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
        with open(os.path.join(out, "summary.json")) as f:
            summary = json.load(f)
    levels = summary["levels"]
    last = levels[-1]["timings"]
    solve_all = sum(level["timings"]["solve"] for level in levels)
    phases_all = sum(sum(level["timings"].get(k, 0.0) for k in ("space", "assemble", "solve", "errors"))
                     for level in levels)
    return {
        "dofs": levels[-1]["dofs"],
        "levels": len(levels),
        "space": last.get("space", 0.0),
        "assemble": last.get("assemble", 0.0),
        "solve": last.get("solve", 0.0),
        "errors": last.get("errors", 0.0),
        "vtk": summary.get("t_vtk"),
        "other": wall - phases_all,
        "wall": wall,
        "cpu": cpu,
        "ratio": (wall - solve_all) / solve_all if solve_all > 0 else float("nan"),
    }


def median(values):
    values = sorted(values)
    return values[len(values) // 2]


def print_table(binary, threads, rows):
    print(f"\n# {binary}, OMP_NUM_THREADS={threads}")
    print("| space, problem | DOFs | space | assembly + load | factorize + solve | error norms "
          "| VTK + rest | wall [CPU] | rest / factorize |")
    print("|---|---|---|---|---|---|---|---|---|")
    for name, r in rows:
        levels = "" if r["levels"] == 1 else f" (last of {r['levels']} levels)"
        print(f"| {name}{levels} | {r['dofs']:,} | {r['space']:.2f} | {r['assemble']:.2f} | {r['solve']:.2f} "
              f"| {r['errors']:.2f} | {r['other']:.2f} | {r['wall']:.2f} [{r['cpu']:.2f}] "
              f"| {r['ratio']:.2f} |".replace(",", " "))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--binary", action="append",
                        help="iga-run to measure (default build/iga-run); several: run case by case, "
                             "alternating, so that all see the same machine load")
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--repeat", type=int, default=1, help="runs per case; the median wall time is shown")
    parser.add_argument("--only", action="append", help="config stem(s) to run, e.g. ws4-plate")
    parser.add_argument("--json", help="write the raw numbers here")
    args = parser.parse_args()

    binaries = [os.path.abspath(b) for b in (args.binary or ["build/iga-run"])]
    print(f"# OMP_NUM_THREADS={args.threads}, load average before: "
          f"{' '.join(f'{x:.2f}' for x in os.getloadavg())}", flush=True)
    tables = {b: [] for b in binaries}
    raw = {b: {} for b in binaries}
    for name, file in CASES:
        stem = file.rsplit(".", 1)[0]
        if args.only and stem not in args.only:
            continue
        for b in binaries:
            runs = [run_once(b, os.path.join(HERE, "configs", file), args.threads) for _ in range(args.repeat)]
            runs.sort(key=lambda r: r["wall"])
            tables[b].append((name, runs[len(runs) // 2]))
            raw[b][stem] = runs
            print(f"# done: {name} with {b} (load {os.getloadavg()[0]:.2f})", flush=True)
    for b in binaries:
        print_table(b, args.threads, tables[b])
    print(f"\n# load average after: {' '.join(f'{x:.2f}' for x in os.getloadavg())}")
    if args.json:
        with open(args.json, "w") as f:
            json.dump(raw, f, indent=1)


if __name__ == "__main__":
    sys.exit(main())
