#include "spaces/surface_patch/surface_patch_from_config.hpp"

#include <stdexcept>

#include "config/errors.hpp"
#include "mesh/gismo_xml.hpp"
#include "mesh/mesh_file_from_config.hpp"
#include "spaces/bspline/bspline_from_config.hpp"
#include "spaces/surface_patch/surface_patch_shapes.hpp"
#include "spaces/surface_patch/surface_patch_space.hpp"

namespace iga {

namespace {

double number(const ConfigNode& domain, const std::string& key, double fallback) {
  const auto n = domain.find(key);
  return n ? n->as_double() : fallback;
}

std::shared_ptr<const NurbsSurfaceMap> read_file(const ConfigNode& domain) {
  const MeshFileRequest request = mesh_file_request(domain);
  if (request.extension != ".xml")
    domain["file"].fail("a surface patch is read from a G+Smo .xml file (got '" + request.path.filename().string() + "')");
  std::array<bool, 2> periodic{false, false};
  if (const auto pn = domain.find("periodic")) {
    const std::string p = pn->as_choice({"none", "u", "v", "both"});
    periodic = {p == "u" || p == "both", p == "v" || p == "both"};
  }
  return domain["file"].guard([&] {
    const std::string path = request.path.string();
    GismoXmlLimits limits;
    limits.planar = false;
    const GismoMultiPatch file = read_gismo_xml(path, limits);
    const GismoPatch& p = single_gismo_patch(file, "bspline on a surface_patch");
    std::vector<Eigen::Vector3d> points;
    for (std::size_t i = 0; i < p.control_points.size(); ++i)
      points.emplace_back(p.control_points[i].x(), p.control_points[i].y(), p.z[i]);
    return build_from_gismo_patch(path, p, [&] {
      return std::make_shared<const NurbsSurfaceMap>(
          KnotVector(p.degree[0], p.knots[0]), KnotVector(p.degree[1], p.knots[1]), std::move(points), p.weights,
          periodic,
          std::string(p.weights.empty() ? "B-spline" : "NURBS") + " surface patch from " +
              request.path.filename().string());
    });
  });
}

std::shared_ptr<const NurbsSurfaceMap> make_map(const ConfigNode& domain) {
  if (domain.has("file")) {
    domain.check_keys({"type", "file", "periodic"});
    return read_file(domain);
  }
  if (!domain.has("shape")) domain.fail("a surface_patch needs 'shape' (cylinder, torus, sphere) or 'file' (.xml)");
  const std::string s = domain["shape"].as_choice({"cylinder", "torus", "sphere"});
  if (s == "cylinder") {
    domain.check_keys({"type", "shape", "radius", "length", "half_angle"});
    const double r = number(domain, "radius", 1.0), l = number(domain, "length", 2.0),
                 a = number(domain, "half_angle", 180.0);
    return domain.guard([&] { return nurbs_cylinder(r, l, a); });
  }
  if (s == "torus") {
    domain.check_keys({"type", "shape", "major_radius", "minor_radius"});
    const double R = number(domain, "major_radius", 2.0), r = number(domain, "minor_radius", 1.0);
    return domain.guard([&] { return nurbs_torus(R, r); });
  }
  domain.check_keys({"type", "shape", "radius", "hole", "sweep"});
  const double r = number(domain, "radius", 1.0), hole = number(domain, "hole", 18.0),
               sweep = number(domain, "sweep", 360.0);
  return domain.guard([&] { return nurbs_sphere_zone(r, hole, sweep); });
}

}  // namespace

SpacePtr make_surface_patch_bspline_space(const ConfigNode& domain, const ConfigNode& space, int level) {
  space.check_keys({"type", "degree", "regularity", "elements"});
  const ConfigNode dn = space["degree"];
  const int p = dn.as_int();
  if (p < 1 || p > 12) dn.fail("degree must be in 1..12 (got " + std::to_string(p) + ")");
  const int r = read_regularity(space, p);
  if (level < 0 || level > 12) space.fail("refinement level must be in 0..12 (got " + std::to_string(level) + ")");
  const std::shared_ptr<const NurbsSurfaceMap> map = make_map(domain);
  std::array<int, 2> elements{map->knots(0).num_spans(), map->knots(1).num_spans()};
  const auto en = space.find("elements");
  if (en) {
    const std::vector<int> e = en->as_ints();
    if (e.size() != 2) en->fail("expected [nu, nv] (got " + std::to_string(e.size()) + " numbers)");
    for (int d = 0; d < 2; ++d) {
      const int spans = map->knots(d).num_spans();
      if (e[d] < 1 || e[d] % spans != 0)
        en->fail(std::to_string(e[d]) + " elements along " + (d == 0 ? "u" : "v") + " do not split the " +
                 std::to_string(spans) + " spans of the patch (" + map->description() +
                 ") evenly; use a positive multiple of " + std::to_string(spans));
      elements[d] = e[d];
    }
  }
  for (int& e : elements) e <<= level;
  try {
    return make_surface_patch_space(map, p, r, elements);
  } catch (const std::invalid_argument& e) {
    (en ? *en : space).fail(e.what());
  }
}

DomainFamily surface_patch_domain_family() {
  return {"surface_patch",
          "one exact NURBS patch in 3D: shape (cylinder: radius, length, half_angle; torus: major_radius, "
          "minor_radius; sphere: radius, hole, sweep) or file: .xml (G+Smo, 3D coefficients), periodic",
          "shape",
          {"cylinder", "torus", "sphere"}};
}

}  // namespace iga
