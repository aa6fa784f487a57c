#!/usr/bin/env python3
"""Start-up of iga-run: `--list` and the quickstart study with one level (the "small study"),
median wall and CPU time (user + system, all threads) over N runs each, and the shared libraries
the executable maps. Not a test: numbers for docs/benchmarks.md. Usage:

    benchmarks/startup.py [--runs N] IGA_RUN [IGA_RUN ...]   (e.g. an older build, then build/iga-run)

Wall times mean something only on an idle machine; the CPU time holds under load."""
import argparse
import os
import resource
import shutil
import statistics
import subprocess
import tempfile
import time

SOURCE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def measure(command, runs, cwd):
    walls, cpus = [], []
    for _ in range(runs):
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        start = time.perf_counter()
        subprocess.run(command, cwd=cwd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
        walls.append(time.perf_counter() - start)
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpus.append(after.ru_utime - before.ru_utime + after.ru_stime - before.ru_stime)
    return 1000 * statistics.median(walls), 1000 * statistics.median(cpus)


def libraries(binary):
    out = subprocess.run(["ldd", binary], capture_output=True, text=True).stdout
    return len(out.splitlines())


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--runs", type=int, default=20)
    parser.add_argument("binaries", nargs="+")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as work:
        shutil.copy(os.path.join(SOURCE, "configs", "quickstart.yaml"), work)
        print("| binary | libraries | `--list` wall [CPU] | quickstart `--levels 1` wall [CPU] |")
        print("|---|---|---|---|")
        for binary in args.binaries:
            binary = os.path.abspath(binary)
            lw, lc = measure([binary, "--list"], args.runs, work)
            sw, sc = measure([binary, "quickstart.yaml", "--levels", "1", "-q", "-o", "out"], args.runs, work)
            print(f"| {binary} | {libraries(binary)} | {lw:.0f} ms [{lc:.0f} ms] | {sw:.0f} ms [{sc:.0f} ms] |")


if __name__ == "__main__":
    main()
