#include "spaces/space_catalogue.hpp"

namespace iga {

SpaceCatalogueEntry ws4_catalogue_entry() {
  // ../shared/notes/ws4-c3-quartic.md: S_4^3 on the Wang-Shi split, 51 simplex splines per triangle.
  return {"ws4",
          "C3 quartic Wang-Shi macro-elements on triangulations (51 simplex splines per triangle)",
          {{"unit_square", "[0,1]^2; jitter, seed", "", {}},
           {"rectangle", "min: [x, y], max: [x, y]; jitter, seed", "", {}},
           {"l_shape", "[-1,1]^2 minus [0,1]x[-1,0]; jitter, seed", "", {}},
           {"polygon", "vertices, holes, mesh_size (triangulated by Gmsh); jitter, seed", "", {}},
           {"mesh_file", "file: triangles from .msh, .geo (mesh_size), .obj, .off; jitter, seed", "", {}}}};
}

}  // namespace iga
