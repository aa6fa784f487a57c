#include "config/config_node.hpp"
#include "spaces/bspline/bspline_from_config.hpp"

#include <cmath>

#include <sstream>
#include <stdexcept>

#include "mesh/gismo_xml.hpp"
#include "mesh/mesh_file_from_config.hpp"
#include "spaces/bspline/knot_vector.hpp"
#include "spaces/bspline/tensor_bspline_space.hpp"
#include "spaces/space_catalogue.hpp"
#include "spaces/surface_patch/surface_patch_from_config.hpp"

namespace iga {

namespace {

KnotVector read_knots(const ConfigNode& node, int degree) {
  try {
    return KnotVector(degree, node.as_doubles());
  } catch (const std::invalid_argument& e) {
    node.fail(e.what());
  }
}

PatchGeometry read_patch(const ConfigNode& domain) {
  domain.check_keys({"type", "degree", "knots_u", "knots_v", "control_points", "weights"});
  const ConfigNode dn = domain["degree"];
  const std::vector<int> deg = dn.as_ints();
  if (deg.size() != 2) dn.fail("expected [pu, pv] (got " + std::to_string(deg.size()) + " numbers)");
  if (deg[0] < 1 || deg[1] < 1)
    dn.fail("patch degrees must be >= 1 (got [" + std::to_string(deg[0]) + ", " + std::to_string(deg[1]) + "])");
  const KnotVector ku = read_knots(domain["knots_u"], deg[0]);
  const KnotVector kv = read_knots(domain["knots_v"], deg[1]);

  const ConfigNode cn = domain["control_points"];
  std::vector<Point2> cp;
  for (const ConfigNode& item : cn.items()) cp.push_back(item.as_point());
  const int nu = ku.num_functions(), nv = kv.num_functions();
  if (static_cast<int>(cp.size()) != nu * nv)
    cn.fail("the knot vectors need " + std::to_string(nu) + " x " + std::to_string(nv) + " = " +
            std::to_string(nu * nv) + " control points, numbered i + j*" + std::to_string(nu) + " (got " +
            std::to_string(cp.size()) + ")");
  std::vector<double> w;
  if (auto wn = domain.find("weights")) {
    w = wn->as_doubles();
    if (w.size() != cp.size())
      wn->fail("need one weight per control point: " + std::to_string(cp.size()) + " (got " +
               std::to_string(w.size()) + ")");
    for (size_t i = 0; i < w.size(); ++i)
      if (!(w[i] > 0.0)) wn->fail("weights must be positive (weight " + std::to_string(i) + " is " + format_number(w[i]) + ")");
  }
  return domain.guard([&] {
    return PatchGeometry(ku, kv, std::move(cp), std::move(w),
                         std::string(w.empty() ? "B-spline" : "NURBS") + " patch " + std::to_string(ku.num_spans()) +
                             "x" + std::to_string(kv.num_spans()) + " spans");
  });
}

/// `domain: {type: mesh_file, file: patch.xml}`: the one patch of a G+Smo XML file.
PatchGeometry read_patch_file(const ConfigNode& domain) {
  domain.check_keys({"type", "file"});
  const MeshFileRequest request = mesh_file_request(domain);
  if (request.extension != ".xml")
    domain["file"].fail("the bspline space reads one patch from a G+Smo .xml file (got '" + request.path.filename().string() +
                        "'; meshes of triangles or quadrilaterals: space ws4, g1, g1_4split)");
  return domain["file"].guard([&] {
    const std::string path = request.path.string();
    const GismoMultiPatch file = read_gismo_xml(path);
    const GismoPatch& p = single_gismo_patch(file, "bspline");
    return build_from_gismo_patch(path, p, [&] {
      return PatchGeometry(KnotVector(p.degree[0], p.knots[0]), KnotVector(p.degree[1], p.knots[1]), p.control_points,
                           p.weights,
                           std::string(p.weights.empty() ? "B-spline" : "NURBS") + " patch from " +
                               request.path.filename().string());
    });
  });
}

/// Breakpoints that split each span of `geometry` into `per_span` equal parts.
std::vector<double> subdivide(const KnotVector& geometry, int per_span) {
  const std::vector<double> g = geometry.breakpoints();
  std::vector<double> bp{g.front()};
  for (size_t k = 0; k + 1 < g.size(); ++k) {
    for (int i = 1; i < per_span; ++i) bp.push_back(g[k] + (g[k + 1] - g[k]) * i / per_span);
    bp.push_back(g[k + 1]);
  }
  return bp;
}

/// The geometry of a rectangle, quarter_annulus or patch domain, validated (det J > 0).
std::shared_ptr<const PatchGeometry> make_patch_geometry(const ConfigNode& domain) {
  const std::string type = domain["type"].as_choice({"rectangle", "quarter_annulus", "patch", "mesh_file"});
  std::shared_ptr<const PatchGeometry> g;
  if (type == "rectangle") {
    domain.check_keys({"type", "min", "max"});
    const Point2 lo = domain["min"].as_point(), hi = domain["max"].as_point();
    if (!(lo.x() < hi.x()) || !(lo.y() < hi.y()))
      domain["max"].fail("max must be greater than min in both coordinates (got min = [" + format_number(lo.x()) + ", " +
                         format_number(lo.y()) + "], max = [" + format_number(hi.x()) + ", " + format_number(hi.y()) + "])");
    g = std::make_shared<const PatchGeometry>(PatchGeometry::rectangle(lo, hi));
  } else if (type == "quarter_annulus") {
    domain.check_keys({"type", "inner", "outer"});
    const double r0 = domain["inner"].as_double(), r1 = domain["outer"].as_double();
    if (!(r0 > 0.0)) domain["inner"].fail("the inner radius must be > 0 (got " + format_number(r0) + ")");
    if (!(r0 < r1))
      domain["outer"].fail("the outer radius must be greater than the inner one (got inner = " + format_number(r0) +
                           ", outer = " + format_number(r1) + ")");
    g = std::make_shared<const PatchGeometry>(PatchGeometry::quarter_annulus(r0, r1));
  } else if (type == "mesh_file") {
    g = std::make_shared<const PatchGeometry>(read_patch_file(domain));
  } else {
    g = std::make_shared<const PatchGeometry>(read_patch(domain));
  }
  g->check_orientation(domain.where());
  return g;
}

}  // namespace

int read_regularity(const ConfigNode& space, int p) {
  int r = p - 1;
  if (auto rn = space.find("regularity")) {
    r = rn->as_int();
    if (r < 0 || r > p - 1)
      rn->fail("regularity must be between 0 and degree-1 = " + std::to_string(p - 1) + " (got " +
               std::to_string(r) + ")");
  }
  return r;
}

SpacePtr make_bspline_space(const ConfigNode& domain, const ConfigNode& space, int level) {
  // B-splines on a NURBS patch in 3D are a surface space of their own (spaces/surface_patch/).
  if (domain["type"].as_choice({"rectangle", "quarter_annulus", "patch", "mesh_file", "surface_patch"}) ==
      "surface_patch")
    return make_surface_patch_bspline_space(domain, space, level);
  space.check_keys({"type", "degree", "regularity", "elements"});
  if (space.has("type")) space["type"].as_choice({"bspline"});
  const ConfigNode dn = space["degree"];
  const int p = dn.as_int();
  if (p < 1) dn.fail("B-splines need degree >= 1 (got " + std::to_string(p) + ")");
  const int r = read_regularity(space, p);
  std::vector<int> elements{2, 2};
  const auto en = space.find("elements");
  if (en) {
    elements = en->as_ints();
    if (elements.size() != 2) en->fail("expected [nx, ny] (got " + std::to_string(elements.size()) + " numbers)");
    if (elements[0] < 1 || elements[1] < 1)
      en->fail("element counts must be >= 1 (got [" + std::to_string(elements[0]) + ", " +
               std::to_string(elements[1]) + "])");
  }
  if (level < 0 || level > 20) space.fail("refinement level must be in 0..20 (got " + std::to_string(level) + ")");

  const std::shared_ptr<const PatchGeometry> geometry = make_patch_geometry(domain);
  std::vector<KnotVector> knots;
  const char* dir_name[2] = {"u (x)", "v (y)"};
  for (int d = 0; d < 2; ++d) {
    const KnotVector& g = d == 0 ? geometry->knots_u() : geometry->knots_v();
    const int spans = g.num_spans();
    if (elements[d] % spans != 0) {
      const std::string msg = std::to_string(elements[d]) + " elements along " + dir_name[d] +
                              " do not subdivide the " + std::to_string(spans) +
                              " spans of the domain patch evenly; use a multiple of " + std::to_string(spans);
      if (en) en->fail(msg);
      space.fail(msg + " in 'elements'");
    }
    // Level 0 subdivides each geometry span uniformly; level l inserts midpoints l times.
    KnotVector kv = KnotVector::from_breakpoints(p, r, subdivide(g, elements[d] / spans));
    for (int l = 0; l < level; ++l) kv = kv.refined(p - r);
    knots.push_back(kv);
  }
  return std::make_shared<const TensorBSplineSpace>(geometry, knots[0], knots[1]);
}

std::vector<SpaceRequestSize> bspline_requested_sizes(const ConfigNode& space, int levels) {
  const auto degree = space.find("degree");
  if (!degree || !degree->is_scalar()) return {};
  const double p = degree->as_int();
  const auto regularity = space.find("regularity");
  const double r = regularity ? regularity->as_int() : p - 1;
  std::vector<double> n = {2, 2};
  if (const auto elements = space.find("elements")) n = elements->as_doubles();
  if (p < 1 || r < 0 || r > p - 1 || n.size() != 2 || !(n[0] >= 1 && n[1] >= 1)) return {};  // the builder says why
  std::vector<SpaceRequestSize> sizes;
  for (int level = 0; level < levels; ++level) {
    const double split = std::pow(2.0, level);
    SpaceRequestSize size;
    size.elements = n[0] * n[1] * split * split;
    size.dofs = (n[0] * split * (p - r) + r + 1) * (n[1] * split * (p - r) + r + 1);
    size.element_entries = size.elements * std::pow(p + 1, 4);
    size.basis = "space.elements and space.degree";
    sizes.push_back(size);
  }
  return sizes;
}

SpaceCatalogueEntry bspline_catalogue_entry() {
  return {"bspline",
          "tensor-product B-splines of degree p >= 1, C^r across element edges, 0 <= r <= p-1 (default p-1)",
          {{"rectangle", "min: [x, y], max: [x, y]", "", {}},
           {"quarter_annulus", "inner: r0, outer: r1 (exact NURBS geometry)", "", {}},
           {"patch", "one B-spline or NURBS patch: degree, knots_u, knots_v, control_points, weights", "", {}},
           {"mesh_file", "file: one patch of a G+Smo .xml file", "", {}},
           surface_patch_domain_family()}};
}

}  // namespace iga
