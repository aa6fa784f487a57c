#include "mesh/read_quad_surface_mesh.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <set>

#include "config/errors.hpp"
#include "mesh/text_line_reader.hpp"

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
      reader.fail("unknown OBJ statement '" + t[0] + "' (expected v, f, or one of vn vt vp o g s l usemtl mtllib)");
    }
  }
  if (mesh.quads.empty()) reader.fail("no faces");
  return mesh;
}

QuadSurfaceFile read_off_quad_surface(std::istream& in, const std::string& source) {
  TextLineReader reader{in, source};
  std::vector<std::string> t;
  if (!reader.next(t) || t[0] != "OFF") reader.fail("expected the header 'OFF'");
  std::vector<std::string> counts(t.begin() + 1, t.end());
  if (counts.empty() && !reader.next(counts)) reader.fail("expected 'vertices faces edges' counts");
  if (counts.size() < 2 || counts.size() > 3) reader.fail("expected 'vertices faces edges' counts");
  const long nv = reader.integer(counts[0]), nf = reader.integer(counts[1]);
  if (nv < 0 || nf <= 0) reader.fail("expected a positive number of faces and no negative counts");
  QuadSurfaceFile mesh;
  mesh.source = source;
  for (long v = 0; v < nv; ++v) {
    if (!reader.next(t))
      reader.fail("the file ends after " + std::to_string(v) + " of " + std::to_string(nv) + " vertices");
    if (t.size() != 3) reader.fail("a vertex needs 'x y z'");
    mesh.points.emplace_back(reader.number(t[0]), reader.number(t[1]), reader.number(t[2]));
  }
  for (long f = 0; f < nf; ++f) {
    if (!reader.next(t))
      reader.fail("the file ends after " + std::to_string(f) + " of " + std::to_string(nf) + " faces");
    const long n = reader.integer(t[0]);
    if (n != 4) reader.fail(face_size_error(std::max(n, 0L)));
    if (t.size() < 5) reader.fail("a face lists fewer vertices than its count 4");
    std::array<int, 4> quad{};
    for (int k = 0; k < 4; ++k) {  // tokens after the indices are colour values
      const long id = reader.integer(t[k + 1]);
      if (id < 0 || id >= nv)
        reader.fail("face vertex " + std::to_string(id) + " does not exist (" + std::to_string(nv) +
                    " vertices; OFF indices are 0-based)");
      quad[k] = static_cast<int>(id);
    }
    mesh.quads.push_back(quad);
    mesh.quad_lines.push_back(reader.line);
  }
  if (reader.next(t)) reader.fail("unexpected data after the " + std::to_string(nf) + " faces");
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
