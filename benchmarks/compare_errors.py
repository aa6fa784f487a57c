#!/usr/bin/env python3
"""Same numbers before and after a restructuring: every shipped config run by two iga-run binaries,
their per-level errors compared from summary.json (full double precision; convergence.csv rounds).

  benchmarks/compare_errors.py --before old/iga-run --after build/iga-run [--only ws4-] [--levels N]

A value passes when |a - b| <= rtol * max(|a|, |b|) (default rtol 1e-10), or when both levels are
flagged at the round-off floor (the solver's noise there is not a change). Comparisons (`spaces:`
lists) and geometry studies are compared per study and per row the same way. Prints one line per
config and a summary; exits 1 when any value moved. Not a test: it runs every config, minutes.
"""
import argparse
import glob
import json
import math
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
KEYS = ["l2", "h1", "h2", "energy", "g1_jump", "estimator"]


def run(binary, config, out, levels, extra):
    args = [binary, "-q", "-o", out, config] + (["--levels", str(levels)] if levels else []) + extra
    proc = subprocess.run(args, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    return proc.returncode, proc.stderr.strip()


def summaries(out):
    """Every summary.json under the output folder, keyed by its folder relative to `out`."""
    found = {}
    for path in glob.glob(os.path.join(out, "**", "summary.json"), recursive=True):
        with open(path) as f:
            found[os.path.relpath(os.path.dirname(path), out)] = json.load(f)
    return found


def at_floor(summary, key, level):
    """summary.json lists, per norm, the levels flagged at the round-off floor."""
    floor = summary.get("round_off_floor") or {}
    return isinstance(floor, dict) and level in (floor.get(key) or [])


def compare(a, b, rtol, jump_floor):
    """Worst relative difference over the levels and keys of two summaries, and what differed."""
    worst, notes = 0.0, []
    la, lb = a.get("levels", []), b.get("levels", [])
    if len(la) != len(lb):
        return math.inf, [f"{len(la)} levels vs {len(lb)}"]
    for ra, rb in zip(la, lb):
        if ra.get("dofs") != rb.get("dofs"):
            notes.append(f"level {ra.get('level')}: dofs {ra.get('dofs')} vs {rb.get('dofs')}")
            worst = math.inf
        for key in KEYS:
            x, y = ra.get(key), rb.get(key)
            if x is None and y is None:
                continue
            if x is None or y is None or not isinstance(x, (int, float)) or not isinstance(y, (int, float)):
                if x != y:
                    notes.append(f"level {ra.get('level')} {key}: {x} vs {y}")
                    worst = math.inf
                continue
            if at_floor(a, key, ra.get("level")) and at_floor(b, key, rb.get("level")):
                continue
            # A C1 space's gradient jump is round-off, whose digits follow the order of operations;
            # a break of C1 is orders of magnitude above the floor.
            if key == "g1_jump" and max(abs(x), abs(y)) <= jump_floor:
                continue
            scale = max(abs(x), abs(y))
            d = abs(x - y) / scale if scale > 0 else 0.0
            if d > rtol:
                notes.append(f"level {ra.get('level')} {key}: {x:.17g} vs {y:.17g} (rel {d:.2e})")
            worst = max(worst, d)
    return worst, notes


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--before", required=True)
    ap.add_argument("--after", required=True)
    ap.add_argument("--only", default="", help="run configs whose file name contains this text")
    ap.add_argument("--levels", type=int, default=0, help="cap the levels (0: the config's own)")
    ap.add_argument("--rtol", type=float, default=1e-10)
    ap.add_argument("--jump-floor", type=float, default=1e-9,
                    help="g1_jump values both below this are round-off, not compared")
    ap.add_argument("--configs", default=os.path.join(ROOT, "configs"))
    args = ap.parse_args()
    configs = sorted(c for c in glob.glob(os.path.join(args.configs, "*.yaml")) if args.only in os.path.basename(c))
    moved = 0
    for config in configs:
        name = os.path.basename(config)
        with tempfile.TemporaryDirectory(prefix="iga-cmp-") as tmp:
            outs = [os.path.join(tmp, "before"), os.path.join(tmp, "after")]
            codes = [run(b, config, o, args.levels, []) for b, o in zip([args.before, args.after], outs)]
            if codes[0][0] != codes[1][0]:
                print(f"MOVED  {name}: exit {codes[0][0]} vs {codes[1][0]}: {codes[1][1][:200]}")
                moved += 1
                continue
            if codes[0][0] != 0:
                print(f"same   {name}: both exit {codes[0][0]}")
                continue
            sa, sb = summaries(outs[0]), summaries(outs[1])
            if sa.keys() != sb.keys():
                print(f"MOVED  {name}: studies {sorted(sa)} vs {sorted(sb)}")
                moved += 1
                continue
            worst, notes = 0.0, []
            for key in sa:
                w, n = compare(sa[key], sb[key], args.rtol, args.jump_floor)
                worst = max(worst, w)
                notes += [f"{key}: {t}" if key != "." else t for t in n]
            status = "MOVED " if worst > args.rtol else "same  "
            moved += worst > args.rtol
            print(f"{status} {name}: {len(sa)} stud{'y' if len(sa) == 1 else 'ies'}, worst relative difference {worst:.2e}")
            for t in notes[:8]:
                print(f"         {t}")
        sys.stdout.flush()
    print(f"{len(configs)} configs, {moved} moved (rtol {args.rtol:g})")
    return 1 if moved else 0


if __name__ == "__main__":
    sys.exit(main())
