#include "spaces/space_catalogue.hpp"

namespace iga {

SpaceCatalogueEntry surface_catalogue_entry() {
  // ../shared/notes/rsd-g1-surfaces.md: the RSD surface is G1 (patches of degree 8 or 9); the space
  // on it is C0 (Bernstein triangles composed with the patch maps).
  return {"surface",
          "C0 Bernstein triangles of degree 1..8 on a smooth surface in 3D: G1 RSD patches of degree 8 or 9 "
          "(C0 with method: none)",
          {{"surface", "mesh (level: icosphere only), or file: .obj, .off, .stl, .msh, .geo; normals, tuple, method",
            "mesh", {"icosphere", "octahedron", "tetrahedron", "perturbed_octahedron", "height_field"}}}};
}

}  // namespace iga
