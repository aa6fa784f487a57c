#!/usr/bin/env python3
"""Convergence of B-splines of degree 2..4 for the Poisson problem on the unit square, run through
the iga_run module and plotted with matplotlib (L2 and H1 errors against h, with the optimal slopes).

    PYTHONPATH=build/python /usr/bin/python3 python/examples/convergence_plot.py --output convergence.png
"""

import argparse

import matplotlib

matplotlib.use("Agg")  # a file, no window
import matplotlib.pyplot as plt  # noqa: E402

import iga_run  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--levels", type=int, default=6)
    parser.add_argument("--output", default="convergence.png")
    args = parser.parse_args()

    fig, axes = plt.subplots(1, 2, figsize=(10, 4.5))
    for degree in (2, 3, 4):
        study = iga_run.run({
            "problem": {"pde": "poisson", "exact": "sin(pi*x)*sin(2*pi*y)", "boundary": {"all": "dirichlet"}},
            "domain": {"type": "rectangle", "min": [0, 0], "max": [1, 1]},
            "space": {"type": "bspline", "degree": degree, "elements": [2, 2]},
            "refinement": {"levels": args.levels},
        })
        t = study.table()
        rates = study.summary["least_squares_rates"]
        # The rates between the last two levels (the least-squares fit also sees the coarse levels).
        print("degree %d: dofs %s, last L2 rate %.2f (optimal %d), last H1 rate %.2f (optimal %d), "
              "least-squares %.2f / %.2f"
              % (degree, t["dofs"].astype(int).tolist(), t["rate_l2"][-1], degree + 1, t["rate_h1"][-1], degree,
                 rates["l2"], rates["h1"]))
        for ax, norm in zip(axes, ("l2", "h1")):
            ax.loglog(t["h"], t[norm], "o-", label="degree %d (last rate %.2f)" % (degree, t["rate_" + norm][-1]))
    for ax, title in zip(axes, ("L2 error", "H1 seminorm error")):
        ax.set_xlabel("h")
        ax.set_title(title)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend()
    fig.tight_layout()
    fig.savefig(args.output, dpi=100)
    print("wrote", args.output)


if __name__ == "__main__":
    main()
