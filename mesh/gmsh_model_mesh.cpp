#include "mesh/gmsh_model_mesh.hpp"

#include <gmsh.h>

#include <algorithm>
#include <map>

#include "config/errors.hpp"
#include "mesh/gmsh_model_nodes.hpp"
#include "mesh/planar_coordinates.hpp"
#include "config/text_excerpt.hpp"

namespace iga {

namespace {

constexpr int gmsh_line2 = 1, gmsh_triangle3 = 2, gmsh_quad4 = 3;

/// Physical curve groups: name -> node tag pairs of their line elements.
std::map<std::string, std::vector<std::array<std::size_t, 2>>> physical_curves(const std::string& source) {
  std::map<std::string, std::vector<std::array<std::size_t, 2>>> groups;
  gmsh::vectorpair physical;
  gmsh::model::getPhysicalGroups(physical, 1);
  for (const auto& [dim, tag] : physical) {
    std::string name;
    gmsh::model::getPhysicalName(dim, tag, name);
    if (name.empty()) name = std::to_string(tag);
    std::vector<int> entities;
    gmsh::model::getEntitiesForPhysicalGroup(dim, tag, entities);
    auto& edges = groups[name];
    for (int entity : entities) {
      std::vector<int> types;
      std::vector<std::vector<std::size_t>> element_tags, node_tags;
      gmsh::model::mesh::getElements(types, element_tags, node_tags, 1, entity);
      for (std::size_t t = 0; t < types.size(); ++t) {
        if (types[t] != gmsh_line2)
          throw InputError(source + ": physical curve " + quoted_excerpt(name) + " has elements of type " +
                           gmsh_element_type_name(types[t]) + "; only 2-node lines are supported (Mesh.ElementOrder 1)");
        for (std::size_t k = 0; k + 1 < node_tags[t].size(); k += 2)
          edges.push_back({node_tags[t][k], node_tags[t][k + 1]});
      }
    }
  }
  return groups;
}

}  // namespace

PlanarMesh planar_mesh_from_gmsh_model(const std::string& source) {
  PlanarMesh mesh;
  mesh.source = source;
  std::vector<int> types;
  std::vector<std::vector<std::size_t>> element_tags, node_tags;
  gmsh::model::mesh::getElements(types, element_tags, node_tags, 2);
  std::vector<std::vector<std::size_t>> cells;  // as node tags
  for (std::size_t t = 0; t < types.size(); ++t) {
    if (types[t] != gmsh_triangle3 && types[t] != gmsh_quad4)
      throw InputError(source + ": 2D elements of type " + gmsh_element_type_name(types[t]) +
                       " are not supported; only 3-node triangles and 4-node quadrilaterals (Mesh.ElementOrder 1)");
    const std::size_t n = types[t] == gmsh_triangle3 ? 3 : 4;
    for (std::size_t e = 0; e < element_tags[t].size(); ++e) {
      cells.emplace_back(node_tags[t].begin() + e * n, node_tags[t].begin() + (e + 1) * n);
      mesh.cell_origins.push_back("Gmsh element " + std::to_string(element_tags[t][e]));
    }
  }
  if (cells.empty())
    throw InputError(source +
                     ": the mesh has no triangles or quadrilaterals (no meshed surface: a .geo needs a "
                     "Plane Surface, a .msh its 2D elements)");

  // Only nodes used by cells become vertices, numbered by node tag.
  std::vector<std::size_t> used;
  for (const auto& cell : cells) used.insert(used.end(), cell.begin(), cell.end());
  const GmshUsedNodes nodes = gmsh_used_nodes(used, source, "cell");
  const std::map<std::size_t, int>& vertex_of = nodes.vertex_of;
  mesh.vertices = planar_coordinates(nodes.points, nodes.origins, source);
  for (const auto& cell : cells) {
    std::vector<int> ids;
    for (std::size_t node : cell) ids.push_back(vertex_of.at(node));
    mesh.cells.push_back(std::move(ids));
  }
  for (const auto& [name, edges] : physical_curves(source))
    for (const auto& edge : edges) {
      const auto a = vertex_of.find(edge[0]), b = vertex_of.find(edge[1]);
      if (a == vertex_of.end() || b == vertex_of.end())
        throw InputError(source + ": physical curve " + quoted_excerpt(name) + " has a line element whose node " +
                         std::to_string(a == vertex_of.end() ? edge[0] : edge[1]) + " belongs to no 2D cell");
      mesh.boundary_groups[name].push_back({a->second, b->second});
    }
  orient_cells_counterclockwise(mesh);
  return mesh;
}

}  // namespace iga
