#include "spaces/g1/multipatch_domains.hpp"
#include "spaces/g1_4split/g1_4split_meshes.hpp"
#include "spaces/space_catalogue.hpp"

namespace iga {

SpaceCatalogueEntry g1_4split_catalogue_entry() {
  // ../shared/notes/g1-4split-macropatch.md: G1 gluing with the geometry in the space (isoparametric)
  // makes the functions C1 on a planar domain (section 10.3).
  // Its own fans and grid, and the g1 layouts without triangles (the builder refuses those).
  std::vector<std::string> layouts = g14_domain_names();
  for (const std::string& name : multipatch_domain_names())
    if (!multipatch_domain(name).has_triangles()) layouts.push_back(name);
  return {"g1_4split",
          "4-split macro-patches: on each quadrilateral bidegree (k, k) B-splines split at 1/2 in each direction, "
          "3 <= k <= 10, C^r across the split lines (default r = 1), G1 across mesh edges (C1 in the plane)",
          {{"multipatch", "name: a built-in layout of quadrilaterals", "name", layouts},
           {"mesh_file", "file: quadrilaterals from .msh, .geo (mesh_size, recombine), .obj, .off, G+Smo .xml", "", {}},
           {"surface", "a smooth surface in 3D from a closed quad mesh: mesh, or file: .obj, .off", "mesh",
            {"cube", "split_tetrahedron"}}}};
}

}  // namespace iga
