#include "mesh/read_quad_surface_mesh.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <set>

#include "config/errors.hpp"
#include "mesh/off_records.hpp"
#include "mesh/text_line_reader.hpp"
#include "config/text_excerpt.hpp"

namespace iga {

namespace {

std::string face_size_error(long n) {
  return "a face with " + std::to_string(n) +
         " vertices; a quad surface must consist of quadrilaterals (triangle surfaces take space: surface)";
}

}  // namespace

QuadSurfaceFile read_obj_quad_surface(std::istream& in, const std::string& source) {
  TextLineReader reader{in, source};
  // Normals and texture coordinates do not enter a fitted G1 surface: it makes its own tangent planes.
  const std::set<std::string> ignored = {"vn", "vt", "vp", "o", "g", "s", "l", "usemtl", "mtllib"};
  QuadSurfaceFile mesh;
  mesh.source = source;
  for (std::vector<std::string> t; reader.next(t);) {
    if (t[0] == "v") {
      if (t.size() < 4 || t.size() > 5) reader.fail("a vertex needs 'v x y z [w]'");
      mesh.points.emplace_back(reader.number(t[1]), reader.number(t[2]), reader.number(t[3]));
    } else if (t[0] == "f") {
      if (t.size() != 5) reader.fail(face_size_error(static_cast<long>(t.size()) - 1));
      std::array<int, 4> quad{};
      for (int k = 0; k < 4; ++k)
        quad[k] = reader.obj_index(t[k + 1].substr(0, t[k + 1].find('/')), static_cast<long>(mesh.points.size()),
                                   "face vertex");
      mesh.quads.push_back(quad);
      mesh.quad_lines.push_back(reader.line);
    } else if (!ignored.count(t[0])) {
      reader.fail("unknown OBJ statement " + quoted_excerpt(t[0]) + " (expected v, f, or one of vn vt vp o g s l usemtl mtllib)");
    }
  }
  if (mesh.quads.empty()) reader.fail("no faces");
  return mesh;
}

QuadSurfaceFile read_off_quad_surface(std::istream& in, const std::string& source) {
  TextLineReader reader{in, source};
  const OffRecords off =
      read_off_records(reader, [](long n) { return n == 4 ? std::string() : face_size_error(std::max(n, 0L)); });
  if (off.faces.empty()) reader.fail("no faces");
  QuadSurfaceFile mesh;
  mesh.source = source;
  mesh.points = off.points;
  for (std::size_t f = 0; f < off.faces.size(); ++f) {
    mesh.quads.push_back({off.faces[f][0], off.faces[f][1], off.faces[f][2], off.faces[f][3]});
    mesh.quad_lines.push_back(off.face_lines[f]);
  }
  return mesh;
}

QuadSurfaceFile read_quad_surface_mesh(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext != ".obj" && ext != ".off")
    throw InputError(path + ": unsupported quad surface format '" + ext + "' (expected .obj or .off)");
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open the quad surface file");
  return ext == ".obj" ? read_obj_quad_surface(in, path) : read_off_quad_surface(in, path);
}

}  // namespace iga
