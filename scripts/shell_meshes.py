#!/usr/bin/env python3
"""Quad meshes whose vertices lie on exact shell surfaces, for the Kirchhoff–Love benchmarks on
unstructured layouts (docs/shells.md, "Unstructured layouts"). Each mesh is a level-0 mesh of the
4-split G1 space, which fits its surface to the mesh's bilinear facets once and keeps it under
refinement; so a family of finer meshes (not refinement levels) brings the surface to the exact one.

  cube-sphere  the sphere of radius R: each face of the cube split n x n by equal angles and
               projected radially; 8 valence-3 vertices (the cube's corners), the rest valence 4.
  hemisphere   the pinched hemisphere's zone (R = 10, from the 18° hole to the equator) in rings of
               quads between circles of latitude: m quads around near the hole, 3m near the equator,
               joined by one ring of 1-to-3 transitions (each coarse quad becomes four: two interior
               valence-3 vertices per coarse quad, a valence-6 vertex at each coarse corner). The
               equator has a vertex at every quarter (the four loads) when m is a multiple of 4.

Usage: scripts/shell_meshes.py [OUTPUT_DIR]   (default benchmarks/configs/domains/)
"""
import math
import os
import sys

OUT = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "benchmarks", "configs", "domains")


def write(name, comment, vertices, faces):
    with open(os.path.join(OUT, name), "w") as f:
        for line in comment:
            f.write("# " + line + "\n")
        for p in vertices:
            f.write("v %.17g %.17g %.17g\n" % tuple(p))
        for q in faces:
            f.write("f " + " ".join(str(i + 1) for i in q) + "\n")


class Vertices:
    """Vertices merged by position (rounded), so that faces share the corners they meet at."""

    def __init__(self):
        self.points, self.index = [], {}

    def add(self, p):
        key = tuple(round(c, 9) for c in p)
        if key not in self.index:
            self.index[key] = len(self.points)
            self.points.append(p)
        return self.index[key]


def cube_sphere(n, radius):
    v = Vertices()
    faces = []
    # Each cube face as (normal axis, sign): u, v axes chosen so that (u, v, normal) is right-handed,
    # which orders every face counter-clockwise seen from outside.
    for axis in range(3):
        for sign in (1, -1):
            a, b = (axis + 1) % 3, (axis + 2) % 3
            if sign < 0:
                a, b = b, a
            grid = []
            for j in range(n + 1):
                row = []
                for i in range(n + 1):
                    p = [0.0, 0.0, 0.0]
                    p[axis] = sign
                    p[a] = math.tan(-math.pi / 4 + math.pi / 2 * i / n)
                    p[b] = math.tan(-math.pi / 4 + math.pi / 2 * j / n)
                    s = radius / math.sqrt(sum(c * c for c in p))
                    row.append(v.add([c * s for c in p]))
                grid.append(row)
            for j in range(n):
                for i in range(n):
                    faces.append([grid[j][i], grid[j][i + 1], grid[j + 1][i + 1], grid[j + 1][i]])
    return v.points, faces


def hemisphere_zone(m, radius=10.0, hole=18.0):
    """Rings of quads on the zone hole <= ψ <= 90° (ψ the polar angle), m around near the hole and
    3m near the equator. Rows: r1 coarse, one transition, r2 fine, all of the same height, their
    numbers chosen for roughly square quads."""
    span = math.radians(90.0 - hole)
    # Widths of a coarse quad at 31.5° and of a fine one at 67.5° (the middles of their regions).
    r1 = max(1, round(math.radians(27.0) / (2 * math.pi * math.sin(math.radians(31.5)) / m)))
    r2 = max(1, round(math.radians(45.0) / (2 * math.pi * math.sin(math.radians(67.5)) / (3 * m))))
    rows = r1 + 1 + r2
    v = []

    def point(theta, psi):
        v.append([radius * math.sin(psi) * math.cos(theta), radius * math.sin(psi) * math.sin(theta),
                  radius * math.cos(psi)])
        return len(v) - 1

    def ring(k, n):
        psi = math.radians(hole) + span * k / rows
        return [point(2 * math.pi * i / n, psi) for i in range(n)]

    faces = []
    rings = [ring(k, m) for k in range(r1 + 1)]
    for k in range(r1):
        a, b = rings[k], rings[k + 1]
        faces += [[a[i], a[(i + 1) % m], b[(i + 1) % m], b[i]] for i in range(m)]
    coarse = rings[-1]
    psi_mid = math.radians(hole) + span * (r1 + 0.5) / rows
    inner = [[point(2 * math.pi * (i + t / 3.0) / m, psi_mid) for t in (1, 2)] for i in range(m)]
    fine = [ring(r1 + 1 + k, 3 * m) for k in range(r2 + 1)]
    f0 = fine[0]
    for i in range(m):
        A, B = coarse[i], coarse[(i + 1) % m]
        P, Q = inner[i]
        D = [f0[(3 * i + t) % (3 * m)] for t in range(4)]
        faces += [[A, B, Q, P], [A, P, D[1], D[0]], [P, Q, D[2], D[1]], [Q, B, D[3], D[2]]]
    for k in range(r2):
        a, b = fine[k], fine[k + 1]
        n = 3 * m
        faces += [[a[i], a[(i + 1) % n], b[(i + 1) % n], b[i]] for i in range(n)]
    return v, faces, (r1, r2)


if __name__ == "__main__":
    for n in (1, 2, 4, 8):
        points, faces = cube_sphere(n, 1.0)
        write("shell_cube_sphere_%d.obj" % n,
              ["The unit sphere as a cube-sphere: each cube face split %d x %d by equal angles, vertices" % (n, n),
               "projected radially onto the sphere; 8 valence-3 vertices (scripts/shell_meshes.py)."], points, faces)
    for m in (4, 8, 12, 16):
        points, faces, (r1, r2) = hemisphere_zone(m)
        write("shell_hemisphere_%d.obj" % m,
              ["The pinched hemisphere's zone (R = 10, 18° hole to the equator): %d quads around in %d ring(s) near" % (m, r1),
               "the hole, a ring of 1-to-3 transitions (valence 3 and 6), %d around in %d ring(s) to the equator;" % (3 * m, r2),
               "vertices on the sphere (scripts/shell_meshes.py)."], points, faces)
