#include "mesh/gmsh_model_nodes.hpp"

#include <gmsh.h>

#include "config/errors.hpp"
#include "config/text_excerpt.hpp"

namespace iga {

std::string gmsh_element_type_name(int type) {
  std::string name;
  int dim = 0, order = 0, nodes = 0, primary = 0;
  std::vector<double> local;
  gmsh::model::mesh::getElementProperties(type, name, dim, order, nodes, local, primary);
  return quoted_excerpt(name) + " (Gmsh type " + std::to_string(type) + ")";
}

GmshUsedNodes gmsh_used_nodes(const std::vector<std::size_t>& used, const std::string& source,
                              const std::string& what) {
  GmshUsedNodes nodes;
  for (std::size_t node : used) nodes.vertex_of.emplace(node, 0);
  std::vector<std::size_t> all_tags;
  std::vector<double> coords, parametric;
  gmsh::model::mesh::getNodes(all_tags, coords, parametric, -1, -1, false, false);
  std::map<std::size_t, Eigen::Vector3d> position;
  for (std::size_t k = 0; k < all_tags.size(); ++k)
    if (nodes.vertex_of.count(all_tags[k]))
      position[all_tags[k]] = {coords[3 * k], coords[3 * k + 1], coords[3 * k + 2]};
  for (auto& [node, id] : nodes.vertex_of) {
    const auto it = position.find(node);
    if (it == position.end())
      throw InputError(source + ": a " + what + " uses node " + std::to_string(node) + ", which has no coordinates");
    id = static_cast<int>(nodes.points.size());
    nodes.points.push_back(it->second);
    nodes.origins.push_back("Gmsh node " + std::to_string(node));
  }
  return nodes;
}

}  // namespace iga
