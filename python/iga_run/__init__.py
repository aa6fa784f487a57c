"""iga_run: iga-run's convergence studies and spline spaces from Python.

    import iga_run
    study = iga_run.run("configs/bspline-poisson.yaml")          # or a dict with the same keys
    study.levels          # per-level rows (dicts, as in summary.json)
    study.table()["l2"]   # the same as NumPy arrays, one per column
    study.summary         # summary.json as a dict
    study.solution([[0.5, 0.5]]), study.solution.gradient([[0.5, 0.5]])
    space = iga_run.make_space({"type": "rectangle", "min": [0, 0], "max": [1, 1]},
                               {"type": "bspline", "degree": 3, "elements": [4, 4]})
    space.dimension, space.basis_values([[0.2, 0.3]])

Bad input raises iga_run.InputError (a ValueError) with the place named, as the command line
reports it; a failed solve raises iga_run.NumericalError. See docs/library.md.
"""

import json
import os

import numpy as np

from ._iga_run import InputError, NumericalError, Space, __version__
from . import _iga_run

__all__ = ["run", "make_space", "Study", "Solution", "Space", "InputError", "NumericalError", "__version__"]


def _points(points):
    """(n, 2) float array from a point or a list of points; and whether one point was given."""
    p = np.asarray(points, dtype=float)
    single = p.ndim == 1
    p = np.atleast_2d(p)
    if p.ndim != 2 or p.shape[1] != 2:
        raise ValueError("points must be (x, y) or an (n, 2) array, got shape %s" % (np.shape(points),))
    return np.ascontiguousarray(p), single


class Solution:
    """The discrete solution u_h of a study's finest level: evaluate u_h and grad u_h at points
    (NaN outside the domain)."""

    def __init__(self, space, coefficients):
        self.space = space
        self.coefficients = np.asarray(coefficients)

    def value(self, points):
        p, single = _points(points)
        v = self.space.evaluate(self.coefficients, p)
        return v[0] if single else v

    __call__ = value

    def gradient(self, points):
        p, single = _points(points)
        g = self.space.gradient(self.coefficients, p)
        return g[0] if single else g


class Study:
    """A finished convergence study: `summary` (summary.json as a dict), `levels` (its rows),
    `solution` (the finest level's u_h) and `space` (the finest level's space)."""

    def __init__(self, run_result):
        self.summary = json.loads(run_result.summary)
        self.levels = self.summary["levels"]
        self.space = run_result.space
        self.solution = Solution(run_result.space, run_result.coefficients)

    def table(self):
        """The per-level rows as NumPy arrays, one per column (missing values are NaN)."""
        columns = [k for k, v in self.levels[0].items() if not isinstance(v, (dict, str))]
        return {k: np.array([np.nan if row[k] is None else row[k] for row in self.levels], dtype=float)
                for k in columns}

    def __repr__(self):
        return "<iga_run.Study %s, %d levels>" % (self.summary["space"]["type"], len(self.levels))


def run(config, levels=None, quiet=True):
    """Run the study of a config: a path to a YAML file, or a dict with the config's keys
    (docs/configuration.md). `levels` overrides refinement.levels. Nothing is written to disk."""
    n = 0 if levels is None else int(levels)
    if isinstance(config, dict):
        # JSON is YAML: the dict reaches the same parser and checks as a config file.
        return Study(_iga_run.run_text(json.dumps(config, indent=1), "<dict>", n, quiet))
    return Study(_iga_run.run_file(os.fspath(config), n, quiet))


def make_space(domain, space, level=0):
    """The space of a config's `domain` and `space` sections (dicts), refined `level` times."""
    return _iga_run.make_space(json.dumps({"domain": domain, "space": space}, indent=1), "<dict>", int(level))
