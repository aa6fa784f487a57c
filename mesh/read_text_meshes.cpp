#include "mesh/read_text_meshes.hpp"

#include <charconv>
#include <cmath>
#include <set>
#include <sstream>
#include <vector>

#include "config/errors.hpp"
#include "mesh/off_records.hpp"
#include "mesh/text_line_reader.hpp"
#include "mesh/planar_coordinates.hpp"
#include "config/text_excerpt.hpp"

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
      reader.fail("unknown OBJ statement " + quoted_excerpt(t[0]) + " (expected v, f, or one of vt vn vp o g s l usemtl mtllib)");
    }
  }
  mesh.vertices = planar_coordinates(points, point_origins, source);
  orient_consistently_counterclockwise(mesh);
  return mesh;
}

PlanarMesh read_off_mesh(std::istream& in, const std::string& source) {
  TextLineReader reader{in, source};
  const OffRecords off = read_off_records(reader, [](long n) {
    return n == 3 || n == 4 ? std::string() : cell_kind_error(static_cast<std::size_t>(std::max(n, 0L)));
  });
  std::vector<std::string> origins;
  for (int line : off.point_lines) origins.push_back("line " + std::to_string(line));
  PlanarMesh mesh;
  mesh.source = source;
  mesh.cells = off.faces;
  for (int line : off.face_lines) mesh.cell_origins.push_back("line " + std::to_string(line));
  mesh.vertices = planar_coordinates(off.points, origins, source);
  orient_consistently_counterclockwise(mesh);
  return mesh;
}

}  // namespace iga
