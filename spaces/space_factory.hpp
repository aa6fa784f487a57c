#pragma once
/// @file
/// The registry of spaces: the one place that knows every space type by its config name.

#include <string>
#include <vector>

#include "config/config_node.hpp"
#include "spaces/builds_on_elements.hpp"
#include "spaces/space.hpp"
#include "spaces/space_catalogue.hpp"
#include "spaces/space_request_size.hpp"

namespace iga {

/// Config names of all spaces ("bspline", ...).
std::vector<std::string> space_types();

/// What every space type says of itself (spaces/space_catalogue.hpp), in the order of space_types():
/// `iga-run --list` prints these.
std::vector<SpaceCatalogueEntry> space_catalogue();

/// The domain types built from a planar domain of any space above (a graph surface over it).
std::vector<DomainFamily> lifted_domain_families();

/// Build the space named by space["type"] on `domain`, uniformly refined `level` times.
/// `coarser`, when given, is a space built from the same two nodes at a lower level: the new space
/// may share its expensive level-independent parts (the smooth surface of a surface space) instead
/// of building them again; the caller owns it, the new space keeps what it shares alive.
/// `extent`: SpaceExtent::skeleton builds the spaces that can (BuildsOnElements) without their
/// per-element data, for on_elements to add a part's (a rank of a distributed solve); the
/// others, and graph surfaces (whose conditions are the planar space's), are built whole.
/// Throws InputError naming the config place for anything it cannot build.
SpacePtr make_space(const ConfigNode& domain, const ConfigNode& space, int level, const Space* coarser = nullptr,
                    SpaceExtent extent = SpaceExtent::whole);

/// Levels 0 .. levels - 1 of the space, estimated from the request alone (a g1_4split surface from
/// a file: the file's face, edge and vertex counts, read without building anything), or empty for
/// a space without such an estimate or a request the builder will refuse anyway.
std::vector<SpaceRequestSize> requested_space_sizes(const ConfigNode& domain, const ConfigNode& space, int levels);

}  // namespace iga
