#include "spaces/g1/g1_numbering.hpp"

#include <Eigen/SparseCore>
#include <algorithm>
#include <mutex>
#include <stdexcept>
#include <string>

#include "config/worth_threads.hpp"
#include "spaces/g1/bernstein_face.hpp"
#include "spaces/g1/g1_local_problems.hpp"

namespace iga {

namespace {

bool has_face(const std::vector<FaceCoefficient>& function, int face) {
  return std::any_of(function.begin(), function.end(), [&](const FaceCoefficient& c) { return c.face == face; });
}

/// A function of entity `id` (j-th of it) absent from face `face`; numbered once the counts are known.
struct Absent {
  int face;
  bool vertex;  ///< else an edge
  int id, j;
};

void prefix_sums(std::vector<int>& first, int start) {
  first[0] = start;
  for (size_t i = 1; i < first.size(); ++i) first[i] += first[i - 1];
}

}  // namespace

void G1Numbering::face_dofs(const PatchMesh& mesh, int f, std::vector<int>& out) const {
  std::vector<std::pair<int, int>> ranges;  // [begin, end) of each entity's functions
  const int n = mesh.num_corners(f);
  for (int i = 0; i < n; ++i) {
    const int e = mesh.face_edge(f, i), v = mesh.face(f)[i];
    ranges.push_back({edge_first[e], edge_first[e + 1]});
    ranges.push_back({vertex_first[v], vertex_first[v + 1]});
  }
  ranges.push_back({face_first[f], face_first[f + 1]});
  std::sort(ranges.begin(), ranges.end());
  const auto absent = std::lower_bound(not_on_face.begin(), not_on_face.end(), std::make_pair(f, -1));
  out.clear();
  for (const auto& [begin, end] : ranges)
    for (int g = begin; g < end; ++g)
      if (!std::binary_search(absent, not_on_face.end(), std::make_pair(f, g))) out.push_back(g);
}

G1Numbering number_g1_basis(const PatchMesh& mesh, const std::vector<EdgeGluing>& gluing, int k) {
  check_g1_degree(mesh, k);
  const std::string where = where_of(mesh, k);
  const EdgeCollocation collocation(k);
  G1Numbering n;
  n.degree = k;
  // Counts at [i + 1] first, prefix sums at the end.
  n.edge_first.assign(mesh.num_edges() + 1, 0);
  n.vertex_first.assign(mesh.num_vertices() + 1, 0);
  n.face_first.assign(mesh.num_faces() + 1, 0);
  for (int e = 0; e < mesh.num_edges(); ++e)
    if (const MeshEdge& me = mesh.edge(e); me.boundary()) {  // one unit function per unknown
      std::vector<std::pair<int, int>> unknowns;
      add_edge_rows(mesh, k, me.first.face, me.first.local_edge, 2, 2, unknowns);
      n.edge_first[e + 1] = static_cast<int>(unknowns.size());
    }
  // Each vertex fan with the problems of its interior edges (each edge so solved at both ends,
  // counted at X): nothing outlives the fan.
  FirstError edge_error, vertex_error;
  std::mutex absent_mutex;
  std::vector<Absent> absent;
#pragma omp parallel for schedule(dynamic, 16) if (worth_threads(mesh.num_vertices()))
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    const VertexFan& fan = mesh.fan(v);
    if (fan.face.empty()) continue;
    std::vector<EdgeLocal> local(fan.edge.size());
    std::vector<const EdgeLocal*> at(fan.edge.size(), nullptr);
    std::vector<Absent> here;
    bool complete = true;
    for (size_t t = 0; t < fan.edge.size(); ++t) {
      const int e = fan.edge[t];
      const MeshEdge& me = mesh.edge(e);
      if (me.boundary()) continue;
      const std::string error = solve_g1_edge(mesh, gluing, collocation, k, e, where, local[t]);
      if (!error.empty()) {
        edge_error.offer(e, error);
        complete = false;
        continue;
      }
      at[t] = &local[t];
      if (me.x != v) continue;
      const std::vector<std::vector<FaceCoefficient>> functions = edge_functions(mesh, e, local[t]);
      n.edge_first[e + 1] = static_cast<int>(functions.size());
      for (size_t j = 0; j < functions.size(); ++j)
        for (int face : {me.first.face, me.second.face})
          if (!has_face(functions[j], face)) here.push_back({face, false, e, static_cast<int>(j)});
    }
    if (!complete) continue;  // build_g1_basis stops at the edges
    try {
      const std::vector<std::vector<FaceCoefficient>> functions = build_vertex_functions(mesh, gluing, k, v, at, where);
      n.vertex_first[v + 1] = static_cast<int>(functions.size());
      for (size_t j = 0; j < functions.size(); ++j)
        for (int face : fan.face)
          if (!has_face(functions[j], face)) here.push_back({face, true, v, static_cast<int>(j)});
    } catch (const IncompleteBasis& ex) {
      vertex_error.offer(v, ex.what());
    }
    if (!here.empty()) {
      const std::lock_guard<std::mutex> lock(absent_mutex);
      absent.insert(absent.end(), here.begin(), here.end());
    }
  }
  edge_error.throw_if_any();
  vertex_error.throw_if_any();
  for (int f = 0; f < mesh.num_faces(); ++f)
    n.face_first[f + 1] = static_cast<int>(interior_coefficients(mesh.shape(f), k).size());
  prefix_sums(n.edge_first, 0);
  prefix_sums(n.vertex_first, n.edge_first.back());
  prefix_sums(n.face_first, n.vertex_first.back());
  for (const Absent& a : absent)
    n.not_on_face.push_back({a.face, (a.vertex ? n.vertex_first[a.id] : n.edge_first[a.id]) + a.j});
  std::sort(n.not_on_face.begin(), n.not_on_face.end());
  return n;
}

G1Basis build_g1_basis_on(const PatchMesh& mesh, const std::vector<EdgeGluing>& gluing, const G1Numbering& numbering,
                          const std::vector<int>& faces) {
  const int k = numbering.degree;
  const std::string where = where_of(mesh, k);
  // The entities whose functions are active on `faces`: their edges and corners; the corners'
  // problems need every edge at them.
  std::vector<int> vertices, edges, solved;
  for (int f : faces)
    for (int i = 0; i < mesh.num_corners(f); ++i) {
      vertices.push_back(mesh.face(f)[i]);
      edges.push_back(mesh.face_edge(f, i));
    }
  for (std::vector<int>* list : {&vertices, &edges}) {
    std::sort(list->begin(), list->end());
    list->erase(std::unique(list->begin(), list->end()), list->end());
  }
  for (int v : vertices) solved.insert(solved.end(), mesh.fan(v).edge.begin(), mesh.fan(v).edge.end());
  std::sort(solved.begin(), solved.end());
  solved.erase(std::unique(solved.begin(), solved.end()), solved.end());

  const EdgeCollocation collocation(k);
  std::vector<EdgeLocal> local(solved.size());
  FirstError error;
#pragma omp parallel for schedule(dynamic, 16) if (worth_threads(static_cast<int>(solved.size())))
  for (int i = 0; i < static_cast<int>(solved.size()); ++i) {
    const std::string e = solve_g1_edge(mesh, gluing, collocation, k, solved[i], where, local[i]);
    if (!e.empty()) error.offer(solved[i], e);
  }
  error.throw_if_any();  // the skeleton found none: a programming error if it does
  auto local_of = [&](int e) -> const EdgeLocal* {
    return &local[std::lower_bound(solved.begin(), solved.end(), e) - solved.begin()];
  };
  std::vector<std::vector<std::vector<FaceCoefficient>>> vertex_functions(vertices.size());
  FirstError vertex_error;
#pragma omp parallel for schedule(dynamic, 16) if (worth_threads(static_cast<int>(vertices.size())))
  for (int i = 0; i < static_cast<int>(vertices.size()); ++i) {
    std::vector<const EdgeLocal*> at;
    for (int e : mesh.fan(vertices[i]).edge) at.push_back(local_of(e));
    try {
      vertex_functions[i] = build_vertex_functions(mesh, gluing, k, vertices[i], at, where);
    } catch (const IncompleteBasis& ex) {
      vertex_error.offer(vertices[i], ex.what());
    }
  }
  vertex_error.throw_if_any();

  // The functions in increasing number (edges, vertices, faces, each in order), each appended to
  // the faces of `faces` it has coefficients on, as build_g1_basis appends them.
  G1Basis basis;
  basis.degree = k;
  FaceExtractionAssembly extraction(faces);
  auto add_all = [&](const std::vector<std::vector<FaceCoefficient>>& functions, int first, int next,
                     const char* what, int id) {
    if (static_cast<int>(functions.size()) != next - first)
      throw std::logic_error("G1 basis on faces: " + std::string(what) + " " + std::to_string(id) +
                             " has another number of functions than the skeleton counted");
    for (size_t j = 0; j < functions.size(); ++j) extraction.add(first + static_cast<int>(j), functions[j]);
  };
  for (int e : edges)
    add_all(edge_functions(mesh, e, *local_of(e)), numbering.edge_first[e], numbering.edge_first[e + 1], "edge", e);
  for (size_t i = 0; i < vertices.size(); ++i)
    add_all(vertex_functions[i], numbering.vertex_first[vertices[i]], numbering.vertex_first[vertices[i] + 1],
            "vertex", vertices[i]);
  for (int f : faces) add_all(face_functions(mesh, f, k), numbering.face_first[f], numbering.face_first[f + 1], "face", f);
  extraction.finish(mesh, k, basis);
  return basis;
}

}  // namespace iga
