#include "mesh/gmsh_model_surface.hpp"

#include <gmsh.h>

#include <algorithm>
#include <deque>
#include <map>

#include "config/errors.hpp"
#include "mesh/gmsh_model_nodes.hpp"

namespace iga {

namespace {

constexpr int gmsh_triangle3 = 2;

/// Reverses whole entities so that neighbouring entities traverse their shared edges in opposite
/// directions (breadth first from the first entity of each connected group).
void orient_entities(std::vector<std::array<int, 3>>& triangles, const std::vector<int>& entity_of, int entities) {
  std::vector<std::vector<int>> members(entities);
  for (std::size_t n = 0; n < triangles.size(); ++n) members[entity_of[n]].push_back(static_cast<int>(n));
  // Directed edges of the triangles of every entity, keyed by the undirected edge.
  std::map<std::pair<int, int>, std::vector<std::pair<int, bool>>> uses;  // (entity, forward)
  for (std::size_t n = 0; n < triangles.size(); ++n)
    for (int c = 0; c < 3; ++c) {
      const int a = triangles[n][c], b = triangles[n][(c + 1) % 3];
      uses[{std::min(a, b), std::max(a, b)}].push_back({entity_of[n], a < b});
    }
  // For each entity: its neighbours and whether they agree as given (opposite directions).
  std::vector<std::map<int, bool>> agrees(entities);
  for (const auto& [edge, list] : uses)
    if (list.size() == 2 && list[0].first != list[1].first) {
      const bool same = list[0].second != list[1].second;
      agrees[list[0].first].emplace(list[1].first, same);
      agrees[list[1].first].emplace(list[0].first, same);
    }
  std::vector<int> flip(entities, -1);
  for (int start = 0; start < entities; ++start) {
    if (flip[start] >= 0) continue;
    flip[start] = 0;
    std::deque<int> queue = {start};
    while (!queue.empty()) {
      const int e = queue.front();
      queue.pop_front();
      for (const auto& [f, same] : agrees[e])
        if (flip[f] < 0) {
          flip[f] = same ? flip[e] : 1 - flip[e];
          queue.push_back(f);
        }
    }
  }
  for (int e = 0; e < entities; ++e)
    if (flip[e] == 1)
      for (int n : members[e]) std::swap(triangles[n][1], triangles[n][2]);
}

}  // namespace

SurfaceMeshFile surface_mesh_from_gmsh_model(const std::string& source) {
  SurfaceMeshFile mesh;
  mesh.source = source;
  gmsh::vectorpair surfaces;
  gmsh::model::getEntities(surfaces, 2);
  std::vector<std::array<std::size_t, 3>> cells;  // as node tags
  std::vector<int> entity_of;
  for (std::size_t s = 0; s < surfaces.size(); ++s) {
    std::vector<int> types;
    std::vector<std::vector<std::size_t>> element_tags, node_tags;
    gmsh::model::mesh::getElements(types, element_tags, node_tags, 2, surfaces[s].second);
    for (std::size_t t = 0; t < types.size(); ++t) {
      if (types[t] != gmsh_triangle3)
        throw InputError(source + ": 2D elements of type " + gmsh_element_type_name(types[t]) +
                         " are not supported on surfaces; only 3-node triangles (no recombination, "
                         "Mesh.ElementOrder 1)");
      for (std::size_t e = 0; e < element_tags[t].size(); ++e) {
        cells.push_back({node_tags[t][3 * e], node_tags[t][3 * e + 1], node_tags[t][3 * e + 2]});
        entity_of.push_back(static_cast<int>(s));
        mesh.triangle_origins.push_back("Gmsh element " + std::to_string(element_tags[t][e]));
      }
    }
  }
  if (cells.empty())
    throw InputError(source + ": the mesh has no triangles (no meshed surface: a .geo needs surfaces, a .msh "
                              "or .stl its triangles)");

  std::vector<std::size_t> used;
  for (const auto& cell : cells) used.insert(used.end(), cell.begin(), cell.end());
  GmshUsedNodes nodes = gmsh_used_nodes(used, source, "triangle");
  const std::map<std::size_t, int>& vertex_of = nodes.vertex_of;
  mesh.points = std::move(nodes.points);
  mesh.point_origins = std::move(nodes.origins);
  for (const auto& cell : cells)
    mesh.triangles.push_back({vertex_of.at(cell[0]), vertex_of.at(cell[1]), vertex_of.at(cell[2])});
  orient_entities(mesh.triangles, entity_of, static_cast<int>(surfaces.size()));
  return mesh;
}

}  // namespace iga
