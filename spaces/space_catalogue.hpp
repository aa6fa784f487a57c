#pragma once
/// @file
/// What each space says of itself for `iga-run --list`: its config name, one line on its functions
/// (degree, continuity) and the domain families it is built on. Each space writes its entry next to
/// the config reader that builds it (spaces/<type>/<type>_from_config.cpp), so that the domain
/// types it lists and the ones the reader accepts are edited together; the factory collects them
/// (space_catalogue in spaces/space_factory.hpp). tests/app/catalogue_test.cpp holds every entry
/// to what the space's builder accepts.

#include <string>
#include <vector>

namespace iga {

/// One `domain.type` a space is built on.
struct DomainFamily {
  std::string type;                   ///< the value of domain.type
  std::string keys;                   ///< the rest of the domain block, one short phrase
  std::string builtin_key;            ///< "name" or "mesh" when the family has built-in layouts, else empty
  std::vector<std::string> builtins;  ///< the values of domain.<builtin_key> the space is built on
};

struct SpaceCatalogueEntry {
  std::string type;                   ///< the value of space.type
  std::string description;            ///< the functions of the space: degree, continuity; one line
  std::vector<DomainFamily> domains;  ///< every domain.type the space is built on
};

SpaceCatalogueEntry bspline_catalogue_entry();
SpaceCatalogueEntry ws4_catalogue_entry();
SpaceCatalogueEntry tmesh_catalogue_entry();
SpaceCatalogueEntry g1_catalogue_entry();
SpaceCatalogueEntry g1_4split_catalogue_entry();
SpaceCatalogueEntry surface_catalogue_entry();

}  // namespace iga
