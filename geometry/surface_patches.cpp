#include "geometry/surface_patches.hpp"

#include "geometry/rsd/rsd_surface.hpp"

namespace iga {

SurfacePatches surface_patches_of(const rsd::RsdSurface& surface) {
  const rsd::RsdReport& r = surface.report;
  SurfacePatches out;
  out.patches = surface.patches;
  out.vertices = surface.mesh.triangles;
  out.labels = {{"construction", "rsd"},
                {"tuple", rsd::tuple_name(surface.options.tuple)},
                {"method", rsd::method_name(surface.options.method)}};
  out.measures = {{"patch_degree", r.patch_degree},
                  {"triangles", static_cast<double>(surface.patches.size())},
                  {"interior_edges", r.interior_edges},
                  {"boundary_edges", r.boundary_edges},
                  {"max_g1_residual", r.max_g1_residual},
                  {"max_fold_alpha", r.max_fold_alpha},
                  {"min_regularity", r.min_regularity},
                  {"interpolation_residual", r.interpolation_residual},
                  {"max_z", r.max_z}};
  return out;
}

}  // namespace iga
