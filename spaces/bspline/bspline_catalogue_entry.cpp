#include "spaces/space_catalogue.hpp"

namespace iga {

SpaceCatalogueEntry bspline_catalogue_entry() {
  return {"bspline",
          "tensor-product B-splines of degree p >= 1, C^r across element edges, 0 <= r <= p-1 (default p-1)",
          {{"rectangle", "min: [x, y], max: [x, y]", "", {}},
           {"quarter_annulus", "inner: r0, outer: r1 (exact NURBS geometry)", "", {}},
           {"patch", "one B-spline or NURBS patch: degree, knots_u, knots_v, control_points, weights", "", {}},
           {"mesh_file", "file: one patch of a G+Smo .xml file", "", {}}}};
}

}  // namespace iga
