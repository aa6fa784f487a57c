"""The Python module against the command line: a sweep over degrees gives the numbers of
iga-run's summary.json, solutions evaluate to the exact solution where it lies in the space,
spaces have the dimensions their formulas give, and exported matrices solve (SciPy) to the
solution iga-run wrote. Run by ctest (python_module) with PYTHONPATH at the built package."""

import json
import math
import os
import subprocess
import sys
import tempfile
import unittest

import numpy as np

import iga_run

IGA_RUN = os.environ.get("IGA_RUN_BINARY", "iga-run")
SOURCE = os.environ.get("IGA_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))

try:
    import scipy.io
    import scipy.sparse.linalg
except ImportError:  # the matrix test needs SciPy (python3-scipy)
    scipy = None

try:
    import matplotlib  # noqa: F401
except ImportError:  # the plot example needs matplotlib (python3-matplotlib)
    matplotlib = None


def poisson_config(degree, levels=3):
    return {
        "problem": {"pde": "poisson", "exact": "sin(pi*x)*sin(2*pi*y)", "boundary": {"all": "dirichlet"}},
        "domain": {"type": "rectangle", "min": [0, 0], "max": [1, 1]},
        "space": {"type": "bspline", "degree": degree, "elements": [2, 2]},
        "refinement": {"levels": levels},
        "output": {"vtk": False, "plot": False},
    }


def run_cli(config_path, out_dir):
    subprocess.run([IGA_RUN, config_path, "--quiet", "--output", out_dir], check=True, stdout=subprocess.DEVNULL)
    with open(os.path.join(out_dir, "summary.json")) as f:
        return json.load(f)


class StudyTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.addCleanup(self.tmp.cleanup)

    def test_degree_sweep_reproduces_the_command_line(self):
        for degree in (2, 3, 4):
            config = poisson_config(degree)
            path = os.path.join(self.tmp.name, "p%d.yaml" % degree)
            with open(path, "w") as f:
                json.dump(config, f)  # JSON is YAML
            cli = run_cli(path, os.path.join(self.tmp.name, "out%d" % degree))
            for study in (iga_run.run(config), iga_run.run(path)):
                self.assertEqual(len(study.levels), 3)
                self.assertEqual(study.summary["space"], cli["space"])
                for mine, theirs in zip(study.levels, cli["levels"]):
                    self.assertEqual(mine["dofs"], theirs["dofs"])
                    self.assertEqual(mine["free_dofs"], theirs["free_dofs"])
                    # The same library on the same data: equal up to the solver's round-off.
                    for norm in ("l2", "h1"):
                        self.assertAlmostEqual(mine[norm] / theirs[norm], 1.0, delta=1e-8)
                table = study.table()
                np.testing.assert_array_equal(table["dofs"], [(2 * 2**l + degree) ** 2 for l in range(3)])
                # Rates approach the optimal p+1 (L2) and p (H1) from the second level on.
                self.assertGreater(table["rate_l2"][-1], degree + 1 - 0.5)
                self.assertGreater(table["rate_h1"][-1], degree - 0.5)
                self.assertTrue(math.isnan(table["rate_l2"][0]))

    def test_solution_evaluates_u_and_its_gradient(self):
        # x*y*(1+x) lies in the cubic space: u_h is the exact solution up to round-off.
        config = poisson_config(3, levels=2)
        config["problem"]["exact"] = "x*y*(1+x)"
        study = iga_run.run(config)
        rng = np.random.default_rng(1)
        p = rng.random((50, 2))
        x, y = p[:, 0], p[:, 1]
        np.testing.assert_allclose(study.solution(p), x * y * (1 + x), atol=1e-11)
        np.testing.assert_allclose(study.solution.gradient(p), np.c_[y * (1 + 2 * x), x * (1 + x)], atol=1e-10)
        self.assertAlmostEqual(study.solution([0.5, 0.5]), 0.375, delta=1e-12)
        self.assertTrue(math.isnan(study.solution([1.5, 0.5])))  # outside the domain
        self.assertEqual(study.space.dimension, len(study.solution.coefficients))

    def test_bad_input_names_the_key(self):
        config = poisson_config(3)
        config["space"]["degree"] = 0
        with self.assertRaises(iga_run.InputError) as e:
            iga_run.run(config)
        self.assertIn("<dict>", str(e.exception))
        self.assertIn("space.degree", str(e.exception))
        self.assertIsInstance(e.exception, ValueError)

    def test_xml_domain_gives_the_errors_of_the_built_in(self):
        config = {
            "problem": {"pde": "biharmonic", "exact": "(cos(2*pi*x)-1)*(cos(2*pi*y)-1)", "boundary": {"all": "clamped"}},
            "domain": {"type": "multipatch", "name": "3p_square"},
            "space": {"type": "g1", "degree": 5},
            "refinement": {"levels": 2},
        }
        builtin = iga_run.run(config)
        config["domain"] = {"type": "mesh_file", "file": os.path.join(SOURCE, "configs", "domains", "3p_square.xml")}
        xml = iga_run.run(config)
        for a, b in zip(builtin.levels, xml.levels):
            self.assertEqual(a["dofs"], b["dofs"])
            for norm in ("l2", "h1", "h2"):
                self.assertAlmostEqual(b[norm] / a[norm], 1.0, delta=1e-8)


class SpaceTest(unittest.TestCase):
    def test_bspline_dimension_and_partition_of_unity(self):
        space = iga_run.make_space({"type": "rectangle", "min": [0, 0], "max": [2, 1]},
                                   {"type": "bspline", "degree": 3, "elements": [4, 2]}, level=1)
        self.assertEqual(space.type, "bspline")
        self.assertEqual(space.dimension, (8 + 3) * (4 + 3))
        self.assertEqual(space.num_elements, 32)
        p = np.array([[0.1, 0.2], [1.9, 0.95], [1.0, 0.5]])
        values = space.basis_values(p)
        self.assertEqual(values.shape, (3, space.dimension))
        np.testing.assert_allclose(values.sum(axis=1), 1.0, atol=1e-13)
        np.testing.assert_allclose(space.basis_gradients(p).sum(axis=1), 0.0, atol=1e-11)
        # B-splines are nonnegative.
        self.assertTrue(np.all(values >= -1e-15))

    def test_g1_space_from_the_xml_domain(self):
        xml = iga_run.make_space({"type": "mesh_file", "file": os.path.join(SOURCE, "configs", "domains", "3p_square.xml")},
                                 {"type": "g1", "degree": 5})
        builtin = iga_run.make_space({"type": "multipatch", "name": "3p_square"}, {"type": "g1", "degree": 5})
        self.assertEqual(xml.dimension, builtin.dimension)
        self.assertEqual(xml.num_elements, 3)
        p = np.array([[0.3, 0.3], [0.6, 0.6], [0.9, 0.2]])
        np.testing.assert_allclose(xml.basis_values(p).sum(axis=1), builtin.basis_values(p).sum(axis=1), atol=1e-12)

    def test_unknown_space_is_an_input_error(self):
        with self.assertRaises(iga_run.InputError):
            iga_run.make_space({"type": "rectangle", "min": [0, 0], "max": [1, 1]}, {"type": "nurbs"})


@unittest.skipIf(scipy is None, "SciPy (python3-scipy) is not installed")
class MatrixExportTest(unittest.TestCase):
    def test_exported_systems_solve_to_the_exported_solution(self):
        with tempfile.TemporaryDirectory() as tmp:
            out = os.path.join(tmp, "out")
            summary = run_cli(os.path.join(SOURCE, "configs", "bspline-poisson-matrices.yaml"), out)
            for row in summary["levels"]:
                l = row["level"]
                m = os.path.join(out, "matrices")
                A = scipy.io.mmread(os.path.join(m, "matrix_%d.mtx" % l)).tocsc()
                b = scipy.io.mmread(os.path.join(m, "rhs_%d.mtx" % l)).ravel()
                u = scipy.io.mmread(os.path.join(m, "solution_%d.mtx" % l)).ravel()
                free = np.loadtxt(os.path.join(m, "free_dofs_%d.txt" % l), dtype=int, ndmin=1)
                self.assertEqual(A.shape, (row["free_dofs"], row["free_dofs"]))
                self.assertEqual(len(free), row["free_dofs"])
                self.assertTrue(np.all(np.diff(free) > 0) and free[-1] < row["dofs"])
                self.assertLess(abs(A - A.T).max(), 1e-12 * abs(A).max())  # a symmetric stiffness matrix
                x = scipy.sparse.linalg.spsolve(A, b)
                # Well conditioned (h >= 1/16, quadratic): a direct solve agrees to ~cond * eps.
                self.assertLess(np.linalg.norm(x - u) / np.linalg.norm(u), 1e-9)


@unittest.skipIf(matplotlib is None, "matplotlib (python3-matplotlib) is not installed")
class ExampleScriptTest(unittest.TestCase):
    def test_convergence_plot_example_writes_its_figure(self):
        with tempfile.TemporaryDirectory() as tmp:
            figure = os.path.join(tmp, "convergence.png")
            script = os.path.join(SOURCE, "python", "examples", "convergence_plot.py")
            env = dict(os.environ, MPLBACKEND="Agg")
            r = subprocess.run([sys.executable, script, "--levels", "3", "--output", figure], env=env,
                               capture_output=True, text=True)
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertGreater(os.path.getsize(figure), 1000)
            self.assertIn("degree 3", r.stdout)


if __name__ == "__main__":
    unittest.main()
