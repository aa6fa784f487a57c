#include "spaces/surface/surface_space_from_config.hpp"

#include "geometry/surface_from_config.hpp"
#include "spaces/space_catalogue.hpp"
#include "spaces/surface/surface_space.hpp"

namespace iga {

SpacePtr make_surface_space(const ConfigNode& domain, const ConfigNode& space, int level, const Space* coarser) {
  if (domain["type"].as_choice({"surface"}) != "surface") domain["type"].fail("expected type: surface");
  space.check_keys({"type", "degree"});
  const ConfigNode degree_node = space["degree"];
  const int degree = degree_node.as_int();
  if (degree < 1 || degree > 8) degree_node.fail("degree must be in 1..8 (got " + std::to_string(degree) + ")");
  if (level < 0 || level > 6) domain.fail("surface spaces are refined at most 6 times (4096 sub-triangles per patch)");
  if (const auto* same = dynamic_cast<const SurfaceBernsteinSpace*>(coarser))
    return std::make_shared<SurfaceBernsteinSpace>(same->shared_surface(), degree, 1 << level, same->surface_patches());
  auto surface = std::make_shared<const rsd::RsdSurface>(surface_from_config(domain));
  return std::make_shared<SurfaceBernsteinSpace>(std::move(surface), degree, 1 << level);
}

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
