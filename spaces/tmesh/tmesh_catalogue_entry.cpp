#include "spaces/space_catalogue.hpp"

namespace iga {

SpaceCatalogueEntry tmesh_catalogue_entry() {
  // ../shared/notes/tmesh-generalized-splines.md: sections <1, s, ..., s^(n-2), u(s), v(s)>, C^r with n >= 2r+1.
  return {"tmesh",
          "generalized splines on T-meshes, sections <1, s, ..., s^(n-2), u, v> (poly, trig, hyperbolic), "
          "C^r with 0 <= r <= (n-1)/2 (default (n-1)/2); local refinement",
          {{"rectangle", "min: [x, y], max: [x, y]", "", {}},
           {"l_shape", "min: [x, y], max: [x, y] (the box without its upper-right quarter)", "", {}}}};
}

}  // namespace iga
