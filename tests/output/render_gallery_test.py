"""ctest render_gallery: scripts/render_gallery.py draws one small picture (the warped plate), and
its pixels must show what the gallery promises: an object that fills the frame without being cut
off, coloured through the viridis map from end to end (the colour bar alone shows both ends, the
surface its middle), no colour outside the map but the background and the dark element edges, and
those edges drawn. Run under xvfb-run with IGA_RUN_BINARY set (CMakeLists.txt registers it)."""

import os
import subprocess
import sys
import tempfile
import unittest

import vtk
from matplotlib import colormaps

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
WIDTH, HEIGHT = 480, 320


def read_png(path):
    reader = vtk.vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    dims = image.GetDimensions()
    scalars = image.GetPointData().GetScalars()
    n = scalars.GetNumberOfComponents()
    pixels = [tuple(int(scalars.GetComponent(i, c)) for c in range(3)) for i in range(dims[0] * dims[1])]
    return dims[0], dims[1], pixels  # rows from the bottom up


class RenderGallery(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.work = tempfile.TemporaryDirectory(prefix="iga-render-test-")
        subprocess.run([sys.executable, os.path.join(ROOT, "scripts", "render_gallery.py"),
                        "--iga-run", os.environ["IGA_RUN_BINARY"], "--out", cls.work.name,
                        "--only", "bspline-plate", "--size", str(WIDTH), str(HEIGHT)], check=True)
        cls.width, cls.height, cls.pixels = read_png(os.path.join(cls.work.name, "bspline-plate.png"))
        viridis = colormaps["viridis"]
        cls.viridis = [tuple(round(255 * v) for v in viridis(i / 255.0)[:3]) for i in range(256)]

    @classmethod
    def tearDownClass(cls):
        cls.work.cleanup()

    def nearest_viridis(self, p):
        """Index in the map and squared distance of the map's colour nearest to p."""
        best = min(range(256), key=lambda i: sum((a - b) ** 2 for a, b in zip(p, self.viridis[i])))
        return best, sum((a - b) ** 2 for a, b in zip(p, self.viridis[best]))

    def test_size(self):
        self.assertEqual((self.width, self.height), (WIDTH, HEIGHT))

    def test_object_fills_the_frame_without_being_cut_off(self):
        plot_width = int(0.84 * WIDTH)  # left of the colour bar's strip
        drawn = [(i % WIDTH, i // WIDTH) for i, p in enumerate(self.pixels)
                 if i % WIDTH < plot_width and p != (255, 255, 255)]
        fraction = len(drawn) / (plot_width * HEIGHT)
        self.assertGreater(fraction, 0.25, "the object should fill a good part of its frame")
        self.assertLess(fraction, 0.9, "no background left: the object is cut off or shown too close")
        # Framed: something drawn in each third across and down, nothing on the frame's edges.
        for third in range(3):
            self.assertTrue(any(third * plot_width // 3 <= x < (third + 1) * plot_width // 3 for x, _ in drawn))
            self.assertTrue(any(third * HEIGHT // 3 <= y < (third + 1) * HEIGHT // 3 for _, y in drawn))
        on_edge = [(x, y) for x, y in drawn if x in (0, plot_width - 1) or y in (0, HEIGHT - 1)]
        self.assertLess(len(on_edge), 0.02 * (2 * plot_width + 2 * HEIGHT), "the object runs off the picture")

    def test_colours_are_viridis_from_end_to_end(self):
        # Lit surfaces darken and brighten the map's colours: a pixel belongs to the map when its
        # colour is a shade (a multiple between 0.4 and 1.6) of a map colour's, with some slack.
        indices, foreign = [], 0
        coloured = [p for p in self.pixels if p != (255, 255, 255) and max(p) - min(p) > 40]
        self.assertGreater(len(coloured), 0.2 * WIDTH * HEIGHT)
        for p in coloured[::7]:
            best, _ = min(((i, self.shade_distance(p, c)) for i, c in enumerate(self.viridis)), key=lambda t: t[1])
            if self.shade_distance(p, self.viridis[best]) < 0.02:
                indices.append(best)
            else:
                foreign += 1
        self.assertLess(foreign, 0.05 * len(coloured[::7]), "colours outside the viridis map (a rainbow?)")
        self.assertLess(min(indices), 16, "the dark (low) end of the map does not appear")
        self.assertGreater(max(indices), 239, "the yellow (high) end of the map does not appear")
        self.assertGreater(len(set(i // 16 for i in indices)), 12, "too few of the map's colours appear")

    @staticmethod
    def shade_distance(p, c):
        """Distance of p's direction in colour space from c's (0: p is a shade of c)."""
        import math
        np_, nc = math.sqrt(sum(a * a for a in p)) or 1, math.sqrt(sum(a * a for a in c)) or 1
        return 1 - sum(a * b for a, b in zip(p, c)) / (np_ * nc)

    def test_element_edges_are_drawn(self):
        # The edges are near-black lines (0.12 grey); lit viridis never gets that dark and grey.
        dark = sum(1 for p in self.pixels if max(p) < 70 and max(p) - min(p) < 25)
        self.assertGreater(dark, 0.003 * WIDTH * HEIGHT, "no element edges")
        self.assertLess(dark, 0.15 * WIDTH * HEIGHT, "the edges cover the surface")


class WangShiSplitLines(unittest.TestCase):
    """The gallery's WS4 picture draws the split from the linear sub-cells iga-run writes: on one
    triangle that must give the split's 39 lines (docs/spaces/ws4.md: 39 lines, 178 vertices)."""

    def test_one_triangle_gives_the_39_lines(self):
        sys.path.insert(0, os.path.join(ROOT, "scripts"))
        import render_gallery
        with tempfile.TemporaryDirectory(prefix="iga-split-test-") as work:
            with open(os.path.join(work, "triangle.off"), "w") as f:
                f.write("OFF\n3 1 0\n0 0 0\n1 0 0\n0.3 0.8 0\n3 0 1 2\n")
            with open(os.path.join(work, "split.yaml"), "w") as f:
                f.write('problem: {pde: poisson, exact: "x*y", boundary: {all: dirichlet}}\n'
                        "domain: {type: mesh_file, file: triangle.off}\n"
                        "space: {type: ws4}\n"
                        "output: {vtk: {cells: linear, samples: 8}, plot: false}\n")
            subprocess.run([os.environ["IGA_RUN_BINARY"], "--quiet", "--levels", "1", "--output", "out",
                            "split.yaml"], check=True, cwd=work, stdout=subprocess.DEVNULL)
            grid = render_gallery.read_vtu(os.path.join(work, "out", "solution_0.vtu"))
            mesh = render_gallery.read_vtu(os.path.join(work, "out", "mesh_0.vtu"))
            self.assertEqual(grid.GetNumberOfPoints(), 178)
            self.assertEqual(render_gallery.split_lines(grid, mesh).GetNumberOfCells(), 39)


if __name__ == "__main__":
    unittest.main()
