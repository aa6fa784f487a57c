#include "mesh/read_text_meshes.hpp"

#include <charconv>
#include <cmath>
#include <set>
#include <sstream>
#include <vector>

#include "config/errors.hpp"
#include "mesh/text_line_reader.hpp"
#include "mesh/planar_coordinates.hpp"

namespace iga {

namespace {

std::string cell_kind_error(std::size_t n) {
  return "a face with " + std::to_string(n) + " vertices; only triangles (3) and quadrilaterals (4) are supported";
}

}  // namespace

PlanarMesh read_obj_mesh(std::istream& in, const std::string& source) {
  TextLineReader reader{in, source};
  const std::set<std::string> ignored = {"vt", "vn", "vp", "o", "g", "s", "l", "usemtl", "mtllib"};
  std::vector<Eigen::Vector3d> points;
  std::vector<std::string> point_origins;
  PlanarMesh mesh;
  mesh.source = source;
  std::vector<int> face_lines;
  for (std::vector<std::string> t; reader.next(t);) {
    if (t[0] == "v") {
      if (t.size() < 3 || t.size() > 5) reader.fail("a vertex needs 'v x y [z [w]]'");
      points.emplace_back(reader.number(t[1]), reader.number(t[2]), t.size() > 3 ? reader.number(t[3]) : 0.0);
      point_origins.push_back("line " + std::to_string(reader.line));
    } else if (t[0] == "f") {
      if (t.size() - 1 != 3 && t.size() - 1 != 4) reader.fail(cell_kind_error(t.size() - 1));
      std::vector<int> cell;
      for (std::size_t k = 1; k < t.size(); ++k) {
        // `i`, `i/t`, `i//n`, `i/t/n`: only the vertex index matters.
        const long i = reader.integer(t[k].substr(0, t[k].find('/')));
        const long nv = static_cast<long>(points.size());
        const long id = i > 0 ? i - 1 : nv + i;  // negative: relative to the vertices read so far
        if (i == 0 || id < 0 || id >= nv)
          reader.fail("face vertex " + std::to_string(i) + " does not exist (" + std::to_string(nv) +
                      " vertices so far; OBJ indices are 1-based)");
        cell.push_back(static_cast<int>(id));
      }
      mesh.cells.push_back(std::move(cell));
      mesh.cell_origins.push_back("line " + std::to_string(reader.line));
    } else if (!ignored.count(t[0])) {
      reader.fail("unknown OBJ statement '" + t[0] + "' (expected v, f, or one of vt vn vp o g s l usemtl mtllib)");
    }
  }
  mesh.vertices = planar_coordinates(points, point_origins, source);
  orient_consistently_counterclockwise(mesh);
  return mesh;
}

PlanarMesh read_off_mesh(std::istream& in, const std::string& source) {
  TextLineReader reader{in, source};
  std::vector<std::string> t;
  if (!reader.next(t) || t[0] != "OFF") reader.fail("expected the header 'OFF'");
  // The counts may follow the header on the same line.
  std::vector<std::string> counts(t.begin() + 1, t.end());
  if (counts.empty() && !reader.next(counts)) reader.fail("expected 'vertices faces edges' counts");
  if (counts.size() < 2 || counts.size() > 3) reader.fail("expected 'vertices faces edges' counts");
  const long nv = reader.integer(counts[0]), nf = reader.integer(counts[1]);
  if (nv < 0 || nf < 0) reader.fail("negative counts");
  std::vector<Eigen::Vector3d> points;
  std::vector<std::string> origins;
  for (long v = 0; v < nv; ++v) {
    if (!reader.next(t))
      reader.fail("the file ends after " + std::to_string(v) + " of " + std::to_string(nv) + " vertices");
    if (t.size() != 3) reader.fail("a vertex needs 'x y z'");
    points.emplace_back(reader.number(t[0]), reader.number(t[1]), reader.number(t[2]));
    origins.push_back("line " + std::to_string(reader.line));
  }
  PlanarMesh mesh;
  mesh.source = source;
  for (long f = 0; f < nf; ++f) {
    if (!reader.next(t))
      reader.fail("the file ends after " + std::to_string(f) + " of " + std::to_string(nf) + " faces");
    const long n = reader.integer(t[0]);
    if (n != 3 && n != 4) reader.fail(cell_kind_error(static_cast<std::size_t>(std::max(n, 0L))));
    if (static_cast<long>(t.size()) < n + 1)
      reader.fail("a face lists fewer vertices than its count " + std::to_string(n));
    std::vector<int> cell;
    for (long k = 1; k <= n; ++k) {  // tokens after the n indices are colour values
      const long id = reader.integer(t[k]);
      if (id < 0 || id >= nv)
        reader.fail("face vertex " + std::to_string(id) + " does not exist (" + std::to_string(nv) +
                    " vertices; OFF indices are 0-based)");
      cell.push_back(static_cast<int>(id));
    }
    mesh.cells.push_back(std::move(cell));
    mesh.cell_origins.push_back("line " + std::to_string(reader.line));
  }
  if (reader.next(t)) reader.fail("unexpected data after the " + std::to_string(nf) + " faces");
  mesh.vertices = planar_coordinates(points, origins, source);
  orient_consistently_counterclockwise(mesh);
  return mesh;
}

}  // namespace iga
