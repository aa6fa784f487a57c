#include "mesh/gmsh_job.hpp"

#include <cstdint>
#include <cstring>
#include <stdexcept>

namespace iga {

namespace {

// Plain little-endian bytes of fixed-size values; both ends are the same build on one machine.
class Writer {
 public:
  template <class T>
  void put(const T& value) {
    out.append(reinterpret_cast<const char*>(&value), sizeof value);
  }
  void put_string(const std::string& s) {
    put<std::uint64_t>(s.size());
    out += s;
  }
  std::string out;
};

class Reader {
 public:
  explicit Reader(std::string_view bytes) : in_(bytes) {}
  template <class T>
  T get() {
    if (in_.size() - at_ < sizeof(T)) throw std::runtime_error("truncated Gmsh worker message");
    T value;
    std::memcpy(&value, in_.data() + at_, sizeof value);
    at_ += sizeof value;
    return value;
  }
  std::uint64_t count(std::size_t item_bytes) {
    const auto n = get<std::uint64_t>();
    if (item_bytes > 0 && n > (in_.size() - at_) / item_bytes)
      throw std::runtime_error("truncated Gmsh worker message");
    return n;
  }
  std::string get_string() {
    const auto n = count(1);
    std::string s(in_.substr(at_, n));
    at_ += n;
    return s;
  }
  bool done() const { return at_ == in_.size(); }

 private:
  std::string_view in_;
  std::size_t at_ = 0;
};

void put_loop(Writer& w, const std::vector<Eigen::Vector2d>& loop) {
  w.put<std::uint64_t>(loop.size());
  for (const auto& x : loop) w.put(x.x()), w.put(x.y());
}

std::vector<Eigen::Vector2d> get_loop(Reader& r) {
  std::vector<Eigen::Vector2d> loop(r.count(16));
  for (auto& x : loop) {
    x.x() = r.get<double>();
    x.y() = r.get<double>();
  }
  return loop;
}

}  // namespace

std::string encode_job(const GmshJob& job) {
  Writer w;
  w.put(job.kind);
  w.put_string(job.path);
  w.put_string(job.source);
  w.put(job.mesh_size);
  w.put(job.recombine);
  w.put(job.surface);
  put_loop(w, job.polygon.outer);
  w.put<std::uint64_t>(job.polygon.holes.size());
  for (const auto& hole : job.polygon.holes) put_loop(w, hole);
  w.put<std::uint64_t>(job.readable_folders.size());
  for (const auto& f : job.readable_folders) w.put_string(f);
  w.put(job.limits);
  return w.out;
}

GmshJob decode_job(std::string_view bytes) {
  Reader r(bytes);
  GmshJob job;
  job.kind = r.get<GmshJob::Kind>();
  job.path = r.get_string();
  job.source = r.get_string();
  job.mesh_size = r.get<double>();
  job.recombine = r.get<bool>();
  job.surface = r.get<bool>();
  job.polygon.outer = get_loop(r);
  job.polygon.holes.resize(r.count(8));
  for (auto& hole : job.polygon.holes) hole = get_loop(r);
  job.readable_folders.resize(r.count(8));
  for (auto& f : job.readable_folders) f = r.get_string();
  job.limits = r.get<MeshLimits>();
  if (!r.done()) throw std::runtime_error("malformed Gmsh job");
  return job;
}

std::string encode_mesh_result(const PlanarMesh& mesh) {
  Writer w;
  w.put('M');
  w.put<std::uint64_t>(mesh.vertices.size());
  for (const auto& x : mesh.vertices) w.put(x.x()), w.put(x.y());
  w.put<std::uint64_t>(mesh.cells.size());
  for (const auto& cell : mesh.cells) {
    w.put<std::uint64_t>(cell.size());
    for (int v : cell) w.put(v);
  }
  w.put<std::uint64_t>(mesh.cell_origins.size());
  for (const auto& o : mesh.cell_origins) w.put_string(o);
  w.put<std::uint64_t>(mesh.boundary_groups.size());
  for (const auto& [name, edges] : mesh.boundary_groups) {
    w.put_string(name);
    w.put<std::uint64_t>(edges.size());
    for (const auto& e : edges) w.put(e[0]), w.put(e[1]);
  }
  return w.out;
}

std::string encode_error_result(const std::string& message) { return "E" + message; }

PlanarMesh decode_mesh(std::string_view bytes, const std::string& source) {
  Reader r(bytes);
  if (r.get<char>() != 'M') throw std::runtime_error("not a mesh message");
  PlanarMesh mesh;
  mesh.source = source;
  mesh.vertices.resize(r.count(16));
  for (auto& x : mesh.vertices) {
    x.x() = r.get<double>();
    x.y() = r.get<double>();
  }
  mesh.cells.resize(r.count(8));
  for (auto& cell : mesh.cells) {
    cell.resize(r.count(4));
    for (int& v : cell) v = r.get<int>();
  }
  mesh.cell_origins.resize(r.count(8));
  for (auto& o : mesh.cell_origins) o = r.get_string();
  const auto groups = r.count(16);
  for (std::uint64_t g = 0; g < groups; ++g) {
    auto& edges = mesh.boundary_groups[r.get_string()];
    edges.resize(r.count(8));
    for (auto& e : edges) e = {r.get<int>(), r.get<int>()};
  }
  if (!r.done()) throw std::runtime_error("malformed Gmsh worker message");
  return mesh;
}

std::string encode_surface_result(const SurfaceMeshFile& mesh) {
  Writer w;
  w.put('S');
  w.put<std::uint64_t>(mesh.points.size());
  for (const auto& x : mesh.points) w.put(x.x()), w.put(x.y()), w.put(x.z());
  w.put<std::uint64_t>(mesh.triangles.size());
  for (const auto& t : mesh.triangles) w.put(t[0]), w.put(t[1]), w.put(t[2]);
  w.put<std::uint64_t>(mesh.point_origins.size());
  for (const auto& o : mesh.point_origins) w.put_string(o);
  w.put<std::uint64_t>(mesh.triangle_origins.size());
  for (const auto& o : mesh.triangle_origins) w.put_string(o);
  return w.out;
}

SurfaceMeshFile decode_surface(std::string_view bytes, const std::string& source) {
  Reader r(bytes);
  if (r.get<char>() != 'S') throw std::runtime_error("not a surface mesh message");
  SurfaceMeshFile mesh;
  mesh.source = source;
  mesh.points.resize(r.count(24));
  for (auto& x : mesh.points) {
    x.x() = r.get<double>();
    x.y() = r.get<double>();
    x.z() = r.get<double>();
  }
  mesh.triangles.resize(r.count(12));
  for (auto& t : mesh.triangles) t = {r.get<int>(), r.get<int>(), r.get<int>()};
  mesh.point_origins.resize(r.count(8));
  for (auto& o : mesh.point_origins) o = r.get_string();
  mesh.triangle_origins.resize(r.count(8));
  for (auto& o : mesh.triangle_origins) o = r.get_string();
  if (!r.done()) throw std::runtime_error("malformed Gmsh worker message");
  return mesh;
}

}  // namespace iga
