#pragma once
/// @file
/// `domain: {type: graph, height: "x^2 - y^2", over: {a planar domain block}}` with any planar
/// `space:` block: the planar space built on `over` (by its own reader, so its keys and messages
/// are those of that domain under `domain.over`), lifted onto the graph z = g(x, y)
/// (graph_surface_space.hpp). The height is refused, naming `domain.height`, when it is not an
/// expression in x and y, when it uses abs, sign or step (a crease), when it is not twice
/// differentiable in closed form, or when it is not finite with its first and second derivatives
/// at the corners, edge midpoints and a few interior points of every element of the level.

#include <functional>

#include "config/config_node.hpp"
#include "spaces/space.hpp"
#include "spaces/space_catalogue.hpp"

namespace iga {

/// Whether `domain` asks for a graph surface (domain.type: graph), without declaring anything.
bool is_graph_domain(const ConfigNode& domain);

/// The graph surface of `domain` over the planar space `build_planar(domain["over"])`.
SpacePtr make_graph_space(const ConfigNode& domain, const ConfigNode& space,
                          const std::function<SpacePtr(const ConfigNode& over)>& build_planar);

/// What `iga-run --list` says of `domain.type: graph`: not one space's domain family but a lift of
/// every planar one, so the listing prints it once after the spaces.
DomainFamily graph_domain_family();

/// The planar space of a graph surface built earlier (the study's previous level), or null.
const Space* planar_of_graph(const Space* space);

}  // namespace iga
