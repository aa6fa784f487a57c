#!/usr/bin/python3
"""Renders docs/gallery/: one picture per space and problem kind, from iga-run's own ParaView files.

Each picture runs iga-run on a small config (below), reads the .vtu files it wrote with VTK and draws
them off screen: the viridis colour map (perceptual, from Matplotlib), a colour bar named after the
field, the element edges (output's mesh_<level>.vtu), lighting on surfaces, and a camera that frames
the object. The comparison plot is iga-run's own comparison.svg.

Debian's VTK draws only through X: run under xvfb-run (ctest render_gallery does), e.g.
  xvfb-run -a -s "-screen 0 1280x1024x24" /usr/bin/python3 scripts/render_gallery.py --iga-run build/iga-run
Options: --out DIR (default docs/gallery), --only NAME ... , --size W H, --list.
Every picture is written anew; the pictures in docs/ are this script's output.
Needs Debian's python3-vtk9 and python3-matplotlib (scripts/install-deps.sh).
"""

import argparse
import os
import shutil
import subprocess
import sys
import tempfile

import vtk
from matplotlib import colormaps

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# What each picture solves. `levels`: iga-run --levels; the picture shows the last level written.
PICTURES = {
    "bspline-plate": dict(
        caption="Clamped plate, cubic C2 B-splines on 8 × 8 elements: u_h warped and coloured by u",
        config="""problem:
  pde: biharmonic
  exact: "(cos(4*pi*x)-1)*(cos(4*pi*y)-1)"
  boundary: {all: clamped}
domain: {type: rectangle, min: [0, 0], max: [1, 1]}
space: {type: bspline, degree: 3, regularity: 2, elements: [8, 8]}
output: {vtk: {levels: last}, plot: false}
""", levels=1, view="warp"),
    "ws4-split": dict(
        caption="WS4 on two triangles (thick lines) and the Wang–Shi split of each (thin lines), "
                "from the linear sub-cells iga-run draws along the split",
        config="""problem:
  pde: biharmonic
  exact: "x^2*(1-x)^2*y^2*(1-y)^2"
  boundary: {all: clamped}
domain: {type: rectangle, min: [0, 0], max: [1, 1]}
space: {type: ws4, elements: [1, 1]}
output: {vtk: {levels: last, cells: linear, samples: 8}, plot: false}
""", levels=1, view="top", subcell_edges=True),
    "tmesh-adaptive": dict(
        caption="Adaptive T-mesh on the L-shape (Poisson, singular at the re-entrant corner): "
                "the mesh of the last level, refined towards the corner",
        config="""problem:
  pde: poisson
  exact: "(x^2 + y^2)^(1/3) * sin(2/3 * (atan2(x - y, -x - y) + 3*pi/4))"
  boundary: {all: dirichlet}
domain: {type: l_shape, min: [-1, -1], max: [1, 1]}
space: {type: tmesh, section: poly, n: 3, regularity: 1, elements: [4, 4]}
refinement: {type: adaptive, marking: 0.5, max_dofs: 3000}
output: {vtk: {levels: last, samples: 4}, plot: false}
""", levels=12, view="top"),
    "g1-multipatch": dict(
        caption="G1 splines of degree 5 on three patches of the square (clamped plate): thick lines "
                "the patches, thin lines the elements; the dot is the extraordinary vertex (valence 3)",
        config="""problem:
  pde: biharmonic
  exact: "(cos(2*pi*x)-1)*(cos(2*pi*y)-1)"
  boundary: {all: clamped}
domain: {type: multipatch, name: 3p_square}
space: {type: g1, degree: 5}
output: {vtk: {levels: all}, plot: false}
""", levels=3, view="top", patches=True),
    "g1_4split-cube": dict(
        caption="Laplace–Beltrami on the cube made a smooth G1 surface by 4-split macro-patches "
                "(degree 5, level 1): u_h with the elements",
        config="""problem:
  pde: laplace_beltrami
  exact: "x*y + sin(z) + x"
domain: {type: surface, mesh: cube}
space: {type: g1_4split, degree: 5}
output: {vtk: {levels: last}, plot: false}
""", levels=2, view="surface"),
    "surface-torus": dict(
        caption="Laplace–Beltrami on a torus meshed by Gmsh, G1 surface with C0 Bernstein "
                "triangles of degree 4: u_h with the elements",
        config="""problem:
  pde: laplace_beltrami
  exact: "x*y + sin(z) + x"
domain: {type: surface, file: domains/torus.geo}
space: {type: surface, degree: 4}
output: {vtk: {levels: last}, plot: false}
""", levels=1, view="surface", files=["domains/torus.geo"]),
    "compare-clamped-plate": dict(
        caption="Four spaces on one clamped plate: |e|_H2 against DOFs and against time "
                "(iga-run's comparison plot, configs/compare-clamped-plate.yaml)",
        config_file="configs/compare-clamped-plate.yaml", levels=4, view="comparison"),
}

BACKGROUND = (1.0, 1.0, 1.0)
EDGE_COLOUR = (0.12, 0.12, 0.12)


def run_iga(iga_run, name, spec, work):
    """Runs iga-run for one picture in its own folder; returns the results folder."""
    folder = os.path.join(work, name)
    os.makedirs(folder)
    if "config_file" in spec:
        config = os.path.join(ROOT, spec["config_file"])
    else:
        config = os.path.join(folder, name + ".yaml")
        with open(config, "w") as f:
            f.write(spec["config"])
        for rel in spec.get("files", []):
            os.makedirs(os.path.dirname(os.path.join(folder, rel)), exist_ok=True)
            shutil.copy(os.path.join(ROOT, "configs", rel), os.path.join(folder, rel))
    out = os.path.join(folder, "results")
    subprocess.run([iga_run, "--quiet", "--levels", str(spec["levels"]), "--output", out, config],
                   check=True, cwd=folder, stdout=subprocess.DEVNULL)
    return out


def read_vtu(path):
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def last_level(folder, prefix):
    levels = [int(f[len(prefix) + 1:-4]) for f in os.listdir(folder)
              if f.startswith(prefix + "_") and f.endswith(".vtu") and f[len(prefix) + 1:-4].isdigit()]
    return max(levels)


def viridis_table(lo, hi):
    table = vtk.vtkLookupTable()
    table.SetNumberOfTableValues(256)
    table.SetRange(lo, hi)
    cmap = colormaps["viridis"]
    for i in range(256):
        r, g, b, _ = cmap(i / 255.0)
        table.SetTableValue(i, r, g, b, 1.0)
    table.Build()
    return table


def surface_of(grid, subdivision=3):
    """The cells' surface as triangles (Lagrange cells subdivided as ParaView draws them), each
    triangle with the id of the cell it came from (array "cell")."""
    surface = vtk.vtkDataSetSurfaceFilter()
    surface.SetInputData(grid)
    surface.SetNonlinearSubdivisionLevel(subdivision)
    surface.PassThroughCellIdsOn()
    surface.SetOriginalCellIdsName("cell")
    surface.Update()
    return surface.GetOutput()


def element_edges(surface, points=None):
    """The cells' boundaries as line segments of the triangulated surface itself: the triangle
    edges between triangles of two cells, or on the boundary. Being edges of the drawn triangles,
    they lie exactly on the surface (no line dips under it); `points` (same ids, e.g. the warped
    surface's) places them."""
    ids = surface.GetCellData().GetArray("cell")
    coords = surface.GetPoints()
    key = {}
    for p in range(surface.GetNumberOfPoints()):  # points shared by cells may be duplicated
        key[p] = tuple(round(x, 9) for x in coords.GetPoint(p))
    sides = {}
    for t in range(surface.GetNumberOfCells()):
        cell = surface.GetCell(t)
        n = cell.GetNumberOfPoints()
        corners = [cell.GetPointId(i) for i in range(n)]
        for a, b in zip(corners, corners[1:] + corners[:1]):
            k = (key[a], key[b]) if key[a] < key[b] else (key[b], key[a])
            sides.setdefault(k, []).append((int(ids.GetTuple1(t)), a, b))
    lines = vtk.vtkCellArray()
    for uses in sides.values():
        if len(uses) == 1 or len({u[0] for u in uses}) > 1:
            lines.InsertNextCell(2)
            lines.InsertCellPoint(uses[0][1])
            lines.InsertCellPoint(uses[0][2])
    out = vtk.vtkPolyData()
    out.SetPoints(points if points is not None else coords)
    out.SetLines(lines)
    return out


def lifted(polydata, dz):
    """A planar drawing moved towards a camera looking down the z axis (lines over the map)."""
    shift = vtk.vtkTransform()
    shift.Translate(0, 0, dz)
    move = vtk.vtkTransformFilter()
    move.SetInputData(polydata)
    move.SetTransform(shift)
    move.Update()
    return move.GetOutput()


def lines_actor(polydata, width, colour=EDGE_COLOUR):
    mapper = vtk.vtkDataSetMapper()
    mapper.SetInputData(polydata)
    mapper.ScalarVisibilityOff()
    actor = vtk.vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(*colour)
    actor.GetProperty().SetLineWidth(width)
    actor.GetProperty().LightingOff()
    return actor


def field_actor(polydata, field, table, lit):
    polydata.GetPointData().SetActiveScalars(field)
    source = polydata
    if lit:
        normals = vtk.vtkPolyDataNormals()
        normals.SetInputData(polydata)
        normals.SplittingOff()
        normals.Update()
        source = normals.GetOutput()
    mapper = vtk.vtkPolyDataMapper()
    mapper.SetInputData(source)
    mapper.SetLookupTable(table)
    mapper.SetScalarModeToUsePointData()
    mapper.SelectColorArray(field)
    mapper.UseLookupTableScalarRangeOn()
    # The edges are drawn on the surface: push the surface back a little so they stay visible.
    mapper.SetResolveCoincidentTopologyToPolygonOffset()
    mapper.SetRelativeCoincidentTopologyPolygonOffsetParameters(1.0, 1.0)
    actor = vtk.vtkActor()
    actor.SetMapper(mapper)
    prop = actor.GetProperty()
    if lit:
        prop.SetAmbient(0.25)
        prop.SetDiffuse(0.75)
        prop.SetSpecular(0.25)
        prop.SetSpecularPower(30)
    else:  # a map seen from above: the colours exactly as in the colour bar
        prop.LightingOff()
    return actor


def colour_bar(table, title, size):
    bar = vtk.vtkScalarBarActor()
    bar.SetLookupTable(table)
    bar.SetTitle(title)
    bar.SetNumberOfLabels(5)
    bar.SetLabelFormat("%-#6.3g")
    bar.SetPosition(0.05, 0.08)
    bar.SetWidth(0.9)
    bar.SetHeight(0.78)
    bar.SetBarRatio(0.3)
    bar.UnconstrainedFontSizeOn()
    font = max(12, size[1] // 32)
    for text in (bar.GetTitleTextProperty(), bar.GetLabelTextProperty()):
        text.SetColor(0.1, 0.1, 0.1)
        text.SetFontSize(font)
        text.ShadowOff()
        text.ItalicOff()
    bar.GetTitleTextProperty().BoldOn()
    bar.SetVerticalTitleSeparation(max(6, size[1] // 60))
    return bar


def split_lines(grid, mesh):
    """The straight lines of a macro-element split, from the edges of its linear sub-cells: the
    collinear runs of edges that go from an element's boundary to an element's boundary. A
    diagonal that only fans a quadrilateral piece into triangles ends inside, and is left out."""
    def rounded(p):
        return tuple(round(x, 9) for x in p[:2])

    boundary = []  # the elements' edges, as segments
    for c in range(mesh.GetNumberOfCells()):
        cell = mesh.GetCell(c)
        pts = [mesh.GetPoint(cell.GetPointId(i))[:2] for i in range(cell.GetNumberOfPoints())]
        boundary += list(zip(pts, pts[1:] + pts[:1]))
    scale = max(max(abs(x) for x in p) for seg in boundary for p in seg) or 1.0

    def on_boundary(p):
        for (ax, ay), (bx, by) in boundary:
            dx, dy = bx - ax, by - ay
            length2 = dx * dx + dy * dy
            if length2 == 0:
                continue
            t = max(0.0, min(1.0, ((p[0] - ax) * dx + (p[1] - ay) * dy) / length2))
            if (ax + t * dx - p[0]) ** 2 + (ay + t * dy - p[1]) ** 2 < (1e-7 * scale) ** 2:
                return True
        return False

    edges = set()
    for c in range(grid.GetNumberOfCells()):
        cell = grid.GetCell(c)
        ids = [cell.GetPointId(i) for i in range(cell.GetNumberOfPoints())]
        for a, b in zip(ids, ids[1:] + ids[:1]):
            pa, pb = rounded(grid.GetPoint(a)), rounded(grid.GetPoint(b))
            if pa != pb:
                edges.add((min(pa, pb), max(pa, pb)))
    # Group the edges by the line they lie on, then walk each line's edges in order.
    lines = {}
    for pa, pb in edges:
        dx, dy = pb[0] - pa[0], pb[1] - pa[1]
        norm = (dx * dx + dy * dy) ** 0.5
        dx, dy = dx / norm, dy / norm
        if dx < -1e-12 or (abs(dx) <= 1e-12 and dy < 0):
            dx, dy = -dx, -dy
        # One line: direction and offset equal to 1e-5 of the drawing's size (the split's lines are
        # much further apart than that, its vertices much closer to their lines).
        key = (dx, dy, (-dy * pa[0] + dx * pa[1]) / scale)
        same = next((k for k in lines if all(abs(a - b) < 1e-5 for a, b in zip(k, key))), key)
        lines.setdefault(same, []).append((pa, pb))
    kept = vtk.vtkPolyData()
    points, cells = vtk.vtkPoints(), vtk.vtkCellArray()
    for (dx, dy, _), segs in lines.items():
        along = []  # (start, end, start point, end point) along the line's direction
        for p, q in segs:
            tp, tq = p[0] * dx + p[1] * dy, q[0] * dx + q[1] * dy
            along.append((tp, tq, p, q) if tp <= tq else (tq, tp, q, p))
        along.sort()
        run = [along[0]]
        for seg in along[1:] + [None]:
            if seg is not None and seg[0] <= run[-1][1] + 1e-7 * scale:  # continues the run
                if seg[1] > run[-1][1]:
                    run.append(seg)
                continue
            first, last = run[0][2], run[-1][3]
            if on_boundary(first) and on_boundary(last):
                cells.InsertNextCell(2)
                cells.InsertCellPoint(points.InsertNextPoint(first[0], first[1], 0.0))
                cells.InsertCellPoint(points.InsertNextPoint(last[0], last[1], 0.0))
            if seg is not None:
                run = [seg]
    kept.SetPoints(points)
    kept.SetLines(cells)
    return kept


def extraordinary_vertices(mesh0):
    """Points where three, or more than four, level-0 patches meet (mesh_0.vtu has one closed
    polyline per patch; a point on k of them is a corner shared by k patches)."""
    patches_at = {}
    for c in range(mesh0.GetNumberOfCells()):
        cell = mesh0.GetCell(c)
        for i in range(cell.GetNumberOfPoints()):
            p = tuple(round(x, 9) for x in mesh0.GetPoint(cell.GetPointId(i)))
            patches_at.setdefault(p, set()).add(c)
    return [p for p, cells in patches_at.items() if len(cells) == 3 or len(cells) > 4]


def render(name, spec, results, out_png, size):
    renderer = vtk.vtkRenderer()
    renderer.SetBackground(*BACKGROUND)
    view = spec["view"]
    level = last_level(results, "solution")
    grid = read_vtu(os.path.join(results, "solution_%d.vtu" % level))
    mesh = read_vtu(os.path.join(results, "mesh_%d.vtu" % level))
    field = "u"
    lo, hi = grid.GetPointData().GetArray(field).GetRange()
    # A bound that is round-off (a clamped plate's zero boundary) is shown as 0.
    lo, hi = (0.0 if abs(v) < 1e-9 * max(abs(lo), abs(hi)) else v for v in (lo, hi))
    table = viridis_table(lo, hi)
    surface = surface_of(grid)

    if view == "warp":
        bounds = surface.GetBounds()
        extent = max(bounds[1] - bounds[0], bounds[3] - bounds[2])
        scale = 0.35 * extent / max(abs(lo), abs(hi), 1e-300)
        surface.GetPointData().SetActiveScalars(field)
        warp = vtk.vtkWarpScalar()
        warp.SetInputData(surface)
        warp.SetNormal(0, 0, 1)
        warp.UseNormalOn()
        warp.SetScaleFactor(scale)
        warp.Update()
        renderer.AddActor(field_actor(warp.GetOutput(), field, table, lit=True))
        renderer.AddActor(lines_actor(element_edges(surface, warp.GetOutput().GetPoints()), 1.6))
    elif view == "top":
        renderer.AddActor(field_actor(surface, field, table, lit=False))
        dz = 1e-3 * surface.GetLength()
        if spec.get("subcell_edges"):
            renderer.AddActor(lines_actor(lifted(split_lines(grid, mesh), dz), 1.0, (0.25, 0.25, 0.25)))
            renderer.AddActor(lines_actor(lifted(mesh, 2 * dz), 3.0))
        elif spec.get("patches"):
            renderer.AddActor(lines_actor(lifted(mesh, dz), 1.0, (0.3, 0.3, 0.3)))
            mesh0 = read_vtu(os.path.join(results, "mesh_0.vtu"))
            renderer.AddActor(lines_actor(lifted(mesh0, 2 * dz), 3.5))
            for p in extraordinary_vertices(mesh0):
                dot = vtk.vtkSphereSource()
                dot.SetCenter(p)
                dot.SetRadius(0.022 * max(surface.GetLength(), 1e-12))
                dot.SetThetaResolution(24)
                dot.SetPhiResolution(24)
                mapper = vtk.vtkPolyDataMapper()
                mapper.SetInputConnection(dot.GetOutputPort())
                actor = vtk.vtkActor()
                actor.SetMapper(mapper)
                actor.GetProperty().SetColor(0.85, 0.1, 0.1)
                actor.GetProperty().LightingOff()
                renderer.AddActor(actor)
        else:
            renderer.AddActor(lines_actor(lifted(mesh, dz), 1.0))
    else:  # a surface in 3D
        renderer.AddActor(field_actor(surface, field, table, lit=True))
        renderer.AddActor(lines_actor(element_edges(surface), 1.3))
        kit = vtk.vtkLightKit()
        kit.AddLightsToRenderer(renderer)

    camera = renderer.GetActiveCamera()
    centre = surface.GetCenter()
    camera.SetFocalPoint(*centre)
    if view == "top":
        camera.SetPosition(centre[0], centre[1], centre[2] + 10.0)
        camera.SetViewUp(0, 1, 0)
        camera.ParallelProjectionOn()
    elif view == "warp":
        camera.SetPosition(centre[0] - 1.2, centre[1] - 2.2, centre[2] + 1.9)
        camera.SetViewUp(0, 0, 1)
    else:
        camera.SetPosition(centre[0] + 2.0, centre[1] - 2.6, centre[2] + 1.6)
        camera.SetViewUp(0, 0, 1)
    renderer.ResetCamera()  # frames the object's bounds from this direction
    camera.Zoom({"top": 1.05, "warp": 1.1}.get(view, 1.15))

    # The object on the left 84 % of the picture, the colour bar in its own strip on the right.
    window = vtk.vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetMultiSamples(8)
    window.SetSize(*size)
    renderer.SetViewport(0.0, 0.0, 0.84, 1.0)
    window.AddRenderer(renderer)
    bar_renderer = vtk.vtkRenderer()
    bar_renderer.SetViewport(0.84, 0.0, 1.0, 1.0)
    bar_renderer.SetBackground(*BACKGROUND)
    bar_renderer.AddActor2D(colour_bar(table, field, size))
    window.AddRenderer(bar_renderer)
    window.Render()
    capture = vtk.vtkWindowToImageFilter()
    capture.SetInput(window)
    capture.ReadFrontBufferOff()
    capture.Update()
    writer = vtk.vtkPNGWriter()
    writer.SetFileName(out_png)
    writer.SetInputConnection(capture.GetOutputPort())
    writer.Write()


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--iga-run", default=os.path.join(ROOT, "build", "iga-run"))
    parser.add_argument("--out", default=os.path.join(ROOT, "docs", "gallery"))
    parser.add_argument("--only", nargs="*", choices=sorted(PICTURES), help="these pictures only")
    parser.add_argument("--size", nargs=2, type=int, metavar=("W", "H"),
                        help="picture size in pixels (default 960 × 640; maps seen from above 800 × 640)")
    parser.add_argument("--list", action="store_true", help="list the pictures and their captions")
    args = parser.parse_args()
    if args.list:
        for name, spec in PICTURES.items():
            print("%-22s %s" % (name, spec["caption"]))
        return 0
    os.makedirs(args.out, exist_ok=True)
    with tempfile.TemporaryDirectory(prefix="iga-gallery-") as work:
        for name in args.only or list(PICTURES):
            spec = PICTURES[name]
            results = run_iga(os.path.abspath(args.iga_run), name, spec, work)
            if spec["view"] == "comparison":
                target = os.path.join(args.out, name + ".svg")
                shutil.copy(os.path.join(results, "comparison.svg"), target)
            else:
                target = os.path.join(args.out, name + ".png")
                size = tuple(args.size) if args.size else (800, 640) if spec["view"] == "top" else (960, 640)
                render(name, spec, results, target, size)
            print(target)
    return 0


if __name__ == "__main__":
    sys.exit(main())
