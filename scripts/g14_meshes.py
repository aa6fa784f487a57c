#!/usr/bin/env python3
"""Writes the quad meshes of docs/spaces/g1_4split.md ("every mesh" study) to configs/domains/:
the fans of spaces/g1_4split/g1_4split_meshes.cpp split once (fan3s/fan5s/fan6s as mesh files, so
that the g1 space can read them too) and an all-valence-4 quad torus (closed surface)."""
import math, os

OUT = os.path.join(os.path.dirname(__file__), "..", "configs", "domains")


def fan(n):
    v = [(0.0, 0.0)]
    r = math.cos(math.pi / n)
    s = [1 + i for i in range(n)]
    for i in range(n):
        v.append((r * math.cos(2 * math.pi * i / n), r * math.sin(2 * math.pi * i / n)))
    c = [1 + n + i for i in range(n)]
    for i in range(n):
        v.append((math.cos((2 * i - 1) * math.pi / n), math.sin((2 * i - 1) * math.pi / n)))
    faces = [[0, s[(i - 1) % n], c[i], s[i]] for i in range(n)]
    return v, faces


def split(v, faces):
    v = list(v)
    mid = {}

    def m(a, b):
        key = (min(a, b), max(a, b))
        if key not in mid:
            mid[key] = len(v)
            v.append(tuple(0.5 * (x + y) for x, y in zip(v[a], v[b])))
        return mid[key]

    out = []
    for q in faces:
        centre = len(v)
        v.append(tuple(sum(v[i][d] for i in q) / 4 for d in range(len(v[0]))))
        for c in range(4):
            out.append([q[c], m(q[c], q[(c + 1) % 4]), centre, m(q[(c + 3) % 4], q[c])])
    return v, out


def write(name, comment, v, faces):
    with open(os.path.join(OUT, name), "w") as f:
        for line in comment:
            f.write("# " + line + "\n")
        for p in v:
            x = list(p) + [0.0] * (3 - len(p))
            f.write("v %.17g %.17g %.17g\n" % tuple(x))
        for q in faces:
            f.write("f " + " ".join(str(i + 1) for i in q) + "\n")


for n in (3, 5, 6):
    v, f = split(*fan(n))
    write("g14_fan%d_split.obj" % n,
          ["The regular %d-gon as %d quads around a valence-%d centre, split once (scripts/g14_meshes.py):" % (n, n, n),
           "its spoke midpoints are interior crossing vertices next to the centre."], v, f)

# Tori: R = 1, r = 0.4, N x M quads, every vertex of valence 4 (closed surfaces in 3D).
for N, M in ((8, 4), (16, 8)):
    R, r = 1.0, 0.4
    v = []
    for i in range(N):
        for j in range(M):
            u, w = 2 * math.pi * i / N, 2 * math.pi * j / M + math.pi / M
            v.append(((R + r * math.cos(w)) * math.cos(u), (R + r * math.cos(w)) * math.sin(u), r * math.sin(w)))
    faces = []
    for i in range(N):
        for j in range(M):
            a, b = i * M + j, ((i + 1) % N) * M + j
            c, d = ((i + 1) % N) * M + (j + 1) % M, i * M + (j + 1) % M
            faces.append([a, b, c, d])
    write("g14_torus_%dx%d.obj" % (N, M),
          ["A quad torus (R = 1, r = 0.4), %d x %d faces, every vertex of valence 4 (scripts/g14_meshes.py)." % (N, M)],
          v, faces)

# Pentagonal trapezohedron (the d10 die): 10 kites, 2 apexes of valence 5, 10 vertices of valence 3.
h, z = 1.0, 0.1056
v = [(0.0, 0.0, h), (0.0, 0.0, -h)]
for i in range(10):
    a = 2 * math.pi * i / 10
    v.append((math.cos(a), math.sin(a), z if i % 2 == 0 else -z))
ring = lambda i: 2 + i % 10
faces = []
for i in range(0, 10, 2):
    faces.append([0, ring(i), ring(i + 1), ring(i + 2)])      # top kite: upper, lower, upper
    faces.append([1, ring(i + 3), ring(i + 2), ring(i + 1)])  # bottom kite: lower, upper, lower
write("g14_trapezohedron.obj", ["Pentagonal trapezohedron: 10 kites, 2 vertices of valence 5 and 10 of valence 3 (scripts/g14_meshes.py)."],
      v, faces)

# 3 x 3 grids of the unit square, irregular: the bilinear map is not in the 4-split space with the
# default gluing, so the level-0 map is fitted (the "fair map" table of docs/spaces/g1_4split.md).
def grid3(move):
    v = [move(i, j, (i / 3.0, j / 3.0)) for j in range(4) for i in range(4)]
    faces = [[4 * j + i, 4 * j + i + 1, 4 * (j + 1) + i + 1, 4 * (j + 1) + i] for j in range(3) for i in range(3)]
    return v, faces


def bump_boundary(i, j, p):  # the 8 boundary points between the corners pushed out by 0.05
    x, y = p
    if (i in (0, 3)) and (j in (0, 3)):
        return p
    return (x - 0.05 * (i == 0) + 0.05 * (i == 3), y - 0.05 * (j == 0) + 0.05 * (j == 3))


def move_inner(i, j, p):  # the 4 inner points moved by 0.07 along one axis and 0.05 along the other
    shift = {(1, 1): (0.07, 0.05), (2, 1): (-0.05, 0.07), (1, 2): (0.05, -0.07), (2, 2): (-0.07, -0.05)}
    d = shift.get((i, j), (0.0, 0.0))
    return (p[0] + d[0], p[1] + d[1])


write("g14_grid3_bumped.obj", ["3 x 3 quads of the unit square, the 8 boundary points between the corners pushed out by 0.05",
                               "(scripts/g14_meshes.py): every inner vertex is a crossing of two bent mesh lines."],
      *grid3(bump_boundary))
write("g14_grid3_moved.obj", ["3 x 3 quads of the unit square, the 4 inner points moved by (0.07, 0.05) in four directions",
                              "(scripts/g14_meshes.py): straight boundary, kinked mesh lines inside."],
      *grid3(move_inner))
