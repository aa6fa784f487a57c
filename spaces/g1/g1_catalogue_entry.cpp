#include "spaces/g1/multipatch_domains.hpp"
#include "spaces/space_catalogue.hpp"

namespace iga {

SpaceCatalogueEntry g1_catalogue_entry() {
  // ../shared/notes/g1-multipatch-mvv.md and g1-routeA-evidence.md: geometry-derived G1 = C1 in the plane.
  return {"g1",
          "one polynomial per (sub-)patch, bidegree (k, k) on quadrilaterals, degree k on triangles, 3 <= k <= 10; "
          "C1 across all interfaces",
          {{"multipatch", "name: a built-in layout", "name", multipatch_domain_names()},
           {"mesh_file", "file: .msh, .geo (mesh_size, recombine), .obj, .off, G+Smo .xml of bilinear patches", "", {}}}};
}

}  // namespace iga
