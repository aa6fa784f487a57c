#!/usr/bin/env python3
"""The shell benchmarks on unstructured layouts (docs/shells.md, "Unstructured layouts"): runs
`iga-run` on a family of quad meshes, one study per mesh (the 4-split surface is fitted once per
mesh, so finer meshes, not levels, bring the geometry to the exact one), and prints a Markdown table.

  hemisphere  benchmarks/configs/shell-pinched-hemisphere-unstructured.yaml on
              configs/domains/shell_hemisphere_m.obj: the radial displacement under a load,
              energy / 8 (the four loads' work), against 0.093 and the KL value 0.09352 of the
              exact patch.
  sphere      a closed sphere under internal pressure on configs/domains/shell_cube_sphere_n.obj
              (fit onto the sphere, or the facets' own fit with --facets): energy against the exact
              p w 4πR², w = p R² (1 − ν) / (2 E t) / (1 + t²/(12 R²)), and the L2 error of u.

Usage: benchmarks/shell_unstructured.py hemisphere --sizes 4 8 12 --levels 2 [--binary build/iga-run]
       benchmarks/shell_unstructured.py sphere --sizes 1 2 4 8 --levels 1
"""
import argparse
import csv
import math
import os
import re
import shutil
import subprocess
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
DOMAINS = os.path.join(HERE, "configs", "domains")

SPHERE = """problem:
  pde: kirchhoff_love_shell
  material: {{youngs_modulus: 1e4, poisson_ratio: 0.3, thickness: 0.01}}
  pressure: 1
  exact: ["{w!r}*x", "{w!r}*y", "{w!r}*z"]
domain: {{type: surface, file: {file}{onto}}}
space: {{type: g1_4split, degree: 4}}
refinement: {{levels: {levels}}}
output: {{vtk: false}}
"""


def run(binary, text, workdir, name, mesh):
    # A config reads files in its own folder only: the mesh goes next to it.
    shutil.copy(mesh, workdir)
    config = os.path.join(workdir, name + ".yaml")
    with open(config, "w") as f:
        f.write(text)
    out = os.path.join(workdir, "out-" + name)
    subprocess.run([binary, config, "--quiet", "--output", out], check=True, stdout=subprocess.DEVNULL)
    with open(os.path.join(out, "convergence.csv")) as f:
        return list(csv.DictReader(f))


def faces(path):
    with open(path) as f:
        return sum(1 for line in f if line.startswith("f "))


def hemisphere(args, workdir):
    with open(os.path.join(HERE, "configs", "shell-pinched-hemisphere-unstructured.yaml")) as f:
        template = f.read()
    print("| mesh m | faces | level | DOFs (3N) | u_r = energy / 8 | vs 0.09352 (KL, exact patch) | vs 0.093 | space + assembly + solve |")
    print("|---|---|---|---|---|---|---|---|")
    for m in args.sizes:
        mesh = os.path.join(DOMAINS, "shell_hemisphere_%d.obj" % m)
        text = re.sub(r"levels: \d+", "levels: %d" % args.levels, template)
        text = re.sub(r"file: [^,]*,", "file: %s," % os.path.basename(mesh), text)
        for row in run(args.binary, text, workdir, "hemisphere-%d" % m, mesh):
            u = float(row["energy"]) / 8
            t = float(row["t_space"]) + float(row["t_assemble"]) + float(row["t_solve"])
            print("| %d | %d | %s | %s | %.6f | %+.2f %% | %+.2f %% | %.1f s |" % (
                m, faces(mesh), row["level"], row["dofs"], u, 100 * (u / 0.09352 - 1), 100 * (u / 0.093 - 1), t),
                flush=True)


def sphere(args, workdir):
    w = 0.7 / (2 * 1e4 * 0.01) / (1 + 1e-4 / 12)
    work, norm = w * 4 * math.pi, w * math.sqrt(4 * math.pi)
    print("| mesh n | faces | level | DOFs (3N) | energy / (p w 4πR²) − 1 | L2 error / ‖u‖ | space + assembly + solve |")
    print("|---|---|---|---|---|---|---|")
    for n in args.sizes:
        mesh = os.path.join(DOMAINS, "shell_cube_sphere_%d.obj" % n)
        onto = "" if args.facets else ", fit_onto: {shape: sphere, radius: 1}"
        text = SPHERE.format(w=w, file=os.path.basename(mesh), onto=onto, levels=args.levels)
        for row in run(args.binary, text, workdir, "sphere-%d" % n, mesh):
            t = float(row["t_space"]) + float(row["t_assemble"]) + float(row["t_solve"])
            print("| %d | %d | %s | %s | %+.2e | %.2e | %.1f s |" % (
                n, faces(mesh), row["level"], row["dofs"], float(row["energy"]) / work - 1, float(row["l2"]) / norm, t),
                flush=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("case", choices=["hemisphere", "sphere"])
    parser.add_argument("--sizes", type=int, nargs="+", required=True)
    parser.add_argument("--levels", type=int, default=1, help="levels per mesh (1: level 0 only)")
    parser.add_argument("--facets", action="store_true", help="sphere: the facets' own fit (no fit_onto)")
    parser.add_argument("--binary", default=os.path.join(HERE, "..", "build", "iga-run"))
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as workdir:
        (hemisphere if args.case == "hemisphere" else sphere)(args, workdir)


if __name__ == "__main__":
    main()
