#include "mesh/read_surface_mesh.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "config/errors.hpp"
#include "mesh/geo_script_check.hpp"
#include "mesh/gmsh_worker.hpp"
#include "mesh/msh_structure_check.hpp"
#include "mesh/stl_structure_check.hpp"
#include "mesh/off_records.hpp"
#include "mesh/text_line_reader.hpp"
#include "config/text_excerpt.hpp"

namespace iga {

namespace {

std::string face_size_error(std::size_t n) {
  return "a face with " + std::to_string(n) + " vertices; surface meshes must consist of triangles";
}

/// Our own checks first, then the Gmsh worker reads (.stl, .msh) or meshes (.geo) the file.
SurfaceMeshFile read_with_gmsh(const std::string& path, const std::string& ext, const SurfaceFileOptions& options,
                               const MeshLimits& limits) {
  namespace fs = std::filesystem;
  std::vector<fs::path> roots = {fs::absolute(path).parent_path()};
  if (!options.config_folder.empty()) roots.push_back(fs::absolute(options.config_folder));
  std::vector<fs::path> inputs = {path};
  GmshJob job;
  if (ext == ".geo") {
    inputs = check_geo_script(path, roots, limits);
    job.kind = GmshJob::mesh_geo;
  } else {
    if (ext == ".msh") check_msh_structure(path, limits);
    if (ext == ".stl") check_stl_structure(path, limits);
    job.kind = ext == ".msh" ? GmshJob::read_msh : GmshJob::read_stl;
    // Gmsh runs "<file>.opt" when it opens <file>, whatever the file is.
    if (std::error_code ec; fs::exists(path + ".opt", ec)) {
      const auto options_file = check_geo_script(path + ".opt", roots, limits);
      inputs.insert(inputs.end(), options_file.begin(), options_file.end());
    }
  }
  job.surface = true;
  job.path = fs::absolute(path).string();
  job.source = path;
  job.mesh_size = options.mesh_size;
  for (const auto& root : roots) job.readable_folders.push_back(root.string());
  job.limits = limits;
  return run_gmsh_surface_job_cached(job, inputs);
}

}  // namespace

SurfaceMeshFile read_obj_surface(std::istream& in, const std::string& source) {
  TextLineReader reader{in, source};
  const std::set<std::string> ignored = {"vt", "vp", "o", "g", "s", "l", "usemtl", "mtllib"};
  SurfaceMeshFile mesh;
  mesh.source = source;
  std::vector<Eigen::Vector3d> file_normals;
  std::vector<int> corner_normal;  // per vertex: index into file_normals, -1 none yet
  std::vector<int> corner_normal_line;
  bool every_corner_has_normal = true;
  for (std::vector<std::string> t; reader.next(t);) {
    if (t[0] == "v") {
      if (t.size() < 4 || t.size() > 5) reader.fail("a vertex needs 'v x y z [w]'");
      mesh.points.emplace_back(reader.number(t[1]), reader.number(t[2]), reader.number(t[3]));
      mesh.point_lines.push_back(reader.line);
      corner_normal.push_back(-1);
      corner_normal_line.push_back(0);
    } else if (t[0] == "vn") {
      if (t.size() != 4) reader.fail("a normal needs 'vn x y z'");
      const Eigen::Vector3d n(reader.number(t[1]), reader.number(t[2]), reader.number(t[3]));
      if (n.norm() == 0.0) reader.fail("a zero normal");
      file_normals.push_back(n.normalized());
    } else if (t[0] == "f") {
      if (t.size() != 4) reader.fail(face_size_error(t.size() - 1));
      std::array<int, 3> tri{};
      for (int k = 0; k < 3; ++k) {
        const std::string& c = t[k + 1];
        const auto slash = c.find('/');
        const int v = reader.obj_index(c.substr(0, slash), static_cast<long>(mesh.points.size()), "face vertex");
        tri[k] = v;
        const auto second = slash == std::string::npos ? std::string::npos : c.find('/', slash + 1);
        if (second == std::string::npos || second + 1 >= c.size()) {
          every_corner_has_normal = false;
          continue;
        }
        const int n = reader.obj_index(c.substr(second + 1), static_cast<long>(file_normals.size()), "normal");
        if (corner_normal[v] < 0) {
          corner_normal[v] = n;
          corner_normal_line[v] = reader.line;
        } else if (corner_normal[v] != n &&
                   file_normals[corner_normal[v]].dot(file_normals[n]) < 1.0 - 1e-12) {
          reader.fail("vertex " + std::to_string(v + 1) + " has a different normal here than on line " +
                      std::to_string(corner_normal_line[v]) +
                      " (a G1 surface has one tangent plane per vertex; drop the 'vn' data to estimate normals)");
        }
      }
      mesh.triangles.push_back(tri);
      mesh.triangle_lines.push_back(reader.line);
    } else if (!ignored.count(t[0])) {
      reader.fail("unknown OBJ statement " + quoted_excerpt(t[0]) + " (expected v, vn, f, or one of vt vp o g s l usemtl mtllib)");
    }
  }
  if (every_corner_has_normal && !mesh.triangles.empty()) {
    for (std::size_t v = 0; v < mesh.points.size(); ++v)
      mesh.normals.push_back(corner_normal[v] >= 0 ? file_normals[corner_normal[v]] : Eigen::Vector3d::Zero());
    // A vertex that no face uses keeps a zero normal; the geometry layer rejects unused vertices.
  }
  return mesh;
}

SurfaceMeshFile read_off_surface(std::istream& in, const std::string& source) {
  TextLineReader reader{in, source};
  const OffRecords off = read_off_records(
      reader, [](long n) { return n == 3 ? std::string() : face_size_error(static_cast<std::size_t>(std::max(n, 0L))); });
  SurfaceMeshFile mesh;
  mesh.source = source;
  mesh.points = off.points;
  mesh.point_lines = off.point_lines;
  for (std::size_t f = 0; f < off.faces.size(); ++f) {
    mesh.triangles.push_back({off.faces[f][0], off.faces[f][1], off.faces[f][2]});
    mesh.triangle_lines.push_back(off.face_lines[f]);
  }
  return mesh;
}

SurfaceMeshFile read_surface_mesh(const std::string& path, const SurfaceFileOptions& options,
                                  const MeshLimits& limits) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext != ".obj" && ext != ".off" && ext != ".stl" && ext != ".msh" && ext != ".geo")
    throw InputError(path + ": unsupported surface mesh format '" + ext + "' (expected .obj, .off, .stl, .msh or .geo)");
  if (!(options.mesh_size >= 0.0)) throw InputError(path + ": mesh size must be >= 0");
  if (options.mesh_size > 0.0 && ext != ".geo")
    throw InputError(path + ": a mesh size applies to .geo files only (a mesh is used as it is)");
  std::ifstream in(path);
  if (!in || std::filesystem::is_directory(path)) throw InputError(path + ": cannot open the surface mesh file");
  if (ext == ".stl" || ext == ".msh" || ext == ".geo") return read_with_gmsh(path, ext, options, limits);
  return ext == ".obj" ? read_obj_surface(in, path) : read_off_surface(in, path);
}

}  // namespace iga
