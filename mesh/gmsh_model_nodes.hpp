#pragma once
/// @file
/// What the readers of a Gmsh model (planar meshes, surfaces) share: element type names for
/// messages, and the nodes their cells use with coordinates. Runs where the Gmsh model lives
/// (the Gmsh worker process).

#include <Eigen/Core>

#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace iga {

/// "'Triangle 6' (Gmsh type 9)": a Gmsh element type for messages.
std::string gmsh_element_type_name(int type);

/// The nodes the cells use, numbered 0, 1, … in tag order: `vertex_of` maps a node tag to its
/// number, `points` and `origins` ("Gmsh node T") are in that order.
struct GmshUsedNodes {
  std::map<std::size_t, int> vertex_of;
  std::vector<Eigen::Vector3d> points;
  std::vector<std::string> origins;
};

/// The coordinates of the node tags in `used` (repeats allowed) from the current Gmsh model.
/// InputError naming `source` if a used node has none ("a `what` uses node T …").
GmshUsedNodes gmsh_used_nodes(const std::vector<std::size_t>& used, const std::string& source,
                              const std::string& what);

}  // namespace iga
