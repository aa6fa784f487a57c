#include "spaces/ws4/ws4_from_config.hpp"

#include <filesystem>
#include <optional>
#include <sstream>

#include "mesh/mesh_file_from_config.hpp"
#include "mesh/mesh_polygon.hpp"
#include "mesh/read_mesh_file.hpp"
#include "spaces/space_catalogue.hpp"
#include "spaces/ws4/mesh_triangulation.hpp"
#include "spaces/ws4/ws4_jitter.hpp"
#include "spaces/ws4/ws4_space.hpp"

namespace iga {

namespace {

std::string box(const Point2& lo, const Point2& hi) {
  std::ostringstream s;
  s << "[" << lo.x() << ", " << hi.x() << "] x [" << lo.y() << ", " << hi.y() << "]";
  return s.str();
}

/// The level-0 mesh of a domain and its description for parameters().
struct BaseMesh {
  std::optional<ws4::Triangulation> mesh;
  std::string description;
};

/// `space.elements`: N or [nx, ny] (default 2 x 2); `single` demands one N.
std::array<int, 2> element_counts(const ConfigNode& space, bool single) {
  int nx = 2, ny = 2;
  if (const auto en = space.find("elements")) {
    if (en->is_sequence()) {
      if (single) en->fail("expected one number N (squares per unit length) for an l_shape domain");
      const std::vector<int> n = en->as_ints();
      if (n.size() != 2) en->fail("expected N or [nx, ny] (got " + std::to_string(n.size()) + " numbers)");
      nx = n[0];
      ny = n[1];
    } else {
      nx = ny = en->as_int();
    }
    if (nx < 1 || ny < 1)
      en->fail("element counts must be >= 1 (got [" + std::to_string(nx) + ", " + std::to_string(ny) + "])");
  }
  return {nx, ny};
}

BaseMesh rectangle_mesh(const ConfigNode& domain, const ConfigNode& space, const std::string& type) {
  const auto [nx, ny] = element_counts(space, false);
  Point2 lo(0, 0), hi(1, 1);
  if (type == "unit_square") {
    domain.check_keys({"type", "jitter", "seed"});
  } else {
    domain.check_keys({"type", "min", "max", "jitter", "seed"});
    lo = domain["min"].as_point();
    hi = domain["max"].as_point();
    if (!(lo.x() < hi.x()) || !(lo.y() < hi.y()))
      domain["max"].fail("max must be greater than min in both coordinates (got " + box(lo, hi) + ")");
  }
  return {ws4::Triangulation::rectangle(nx, ny, lo, hi),
          "rectangle " + box(lo, hi) + ", " + std::to_string(nx) + "x" + std::to_string(ny) + " squares"};
}

BaseMesh l_shape(const ConfigNode& domain, const ConfigNode& space) {
  domain.check_keys({"type", "jitter", "seed"});
  const int n = element_counts(space, true)[0];
  return {ws4::triangulation_from_mesh(ws4::l_shape_mesh(n)), "L-shape [-1,1]^2 minus [0,1]x[-1,0], " +
                                                                  std::to_string(n) + "x" + std::to_string(n) +
                                                                  " squares per unit square"};
}

void reject_elements(const ConfigNode& space, const std::string& type) {
  if (const auto en = space.find("elements"))
    en->fail("'elements' sets the grid of unit_square, rectangle and l_shape domains; a " + type +
             " domain is sized by domain.mesh_size");
}

std::vector<Eigen::Vector2d> points(const ConfigNode& list) {
  if (!list.is_sequence()) list.fail("expected a list of points [[x, y], ...]");
  std::vector<Eigen::Vector2d> result;
  for (const ConfigNode& p : list.items()) result.push_back(p.as_point());
  return result;
}

BaseMesh polygon(const ConfigNode& domain, const ConfigNode& space) {
  domain.check_keys({"type", "vertices", "holes", "mesh_size", "jitter", "seed"});
  reject_elements(space, "polygon");
  PolygonDomain shape;
  shape.outer = points(domain["vertices"]);
  if (const auto holes = domain.find("holes")) {
    if (!holes->is_sequence()) holes->fail("expected a list of polygons [[[x, y], ...], ...]");
    for (const ConfigNode& hole : holes->items()) shape.holes.push_back(points(hole));
  }
  const double h = domain["mesh_size"].as_double();
  if (!(h > 0.0)) domain["mesh_size"].fail("mesh_size must be > 0");
  // Messages name the domain's place; the mesh's own source stays "polygon".
  const PlanarMesh mesh = domain.guard([&] { return mesh_polygon(shape, h, false, "polygon", mesh_limits(domain)); });
  return {domain.guard([&] { return ws4::triangulation_from_mesh(mesh); }),
          "polygon, " + std::to_string(shape.outer.size()) + " vertices, " + std::to_string(shape.holes.size()) +
              (shape.holes.size() == 1 ? " hole" : " holes") + ", mesh size " + format_number(h) + " (Gmsh)"};
}

BaseMesh mesh_file(const ConfigNode& domain, const ConfigNode& space) {
  domain.check_keys({"type", "file", "mesh_size", "jitter", "seed"});
  reject_elements(space, "mesh_file");
  const MeshFileRequest request = mesh_file_request(domain);
  const ConfigNode file = domain["file"];
  const PlanarMesh mesh = file.guard([&] { return read_mesh_file(request.path.string(), request.options); });
  std::string description = "mesh file " + request.path.filename().string();
  if (request.options.mesh_size > 0.0) description += " (mesh size " + format_number(request.options.mesh_size) + ")";
  return {file.guard([&] { return ws4::triangulation_from_mesh(mesh); }), description};
}

}  // namespace

SpacePtr make_ws4_space(const ConfigNode& domain, const ConfigNode& space, int level, SpaceExtent extent) {
  space.check_keys({"type", "elements"});
  if (space.has("type")) space["type"].as_choice({"ws4"});
  if (level < 0 || level > 12) space.fail("refinement level must be in 0..12 (got " + std::to_string(level) + ")");

  const std::string type = domain["type"].as_choice({"unit_square", "rectangle", "l_shape", "polygon", "mesh_file"});
  BaseMesh base = type == "l_shape"     ? l_shape(domain, space)
                  : type == "polygon"   ? polygon(domain, space)
                  : type == "mesh_file" ? mesh_file(domain, space)
                                        : rectangle_mesh(domain, space, type);
  ws4::Triangulation mesh = std::move(*base.mesh);
  for (int l = 0; l < level; ++l) mesh = mesh.refined();
  std::string description = base.description;
  if (const auto jn = domain.find("jitter")) {
    const double jitter = jn->as_double();
    if (!(jitter >= 0.0 && jitter <= 0.2)) jn->fail("jitter must be in [0, 0.2] (fraction of the shortest edge)");
    const int seed = domain.has("seed") ? domain["seed"].as_int() : 1;
    // Each level is jittered afresh from the regular refinement (seed + level: reproducible).
    ws4::jitter_interior_vertices(mesh, jitter, static_cast<unsigned>(seed + level));
    // Thin triangles (possible in file meshes) can be turned over by the moves.
    for (int t = 0; t < mesh.num_triangles(); ++t) {
      const auto& v = mesh.triangle(t);
      const Point2 e1 = mesh.vertices()[v[1]] - mesh.vertices()[v[0]],
                   e2 = mesh.vertices()[v[2]] - mesh.vertices()[v[0]];
      if (!(e1.x() * e2.y() - e1.y() * e2.x() > 0.0))
        jn->fail("the jitter turns over triangle " + std::to_string(t) + " of level " + std::to_string(level) +
                 " (seed " + std::to_string(seed) + "); use a smaller jitter");
    }
    std::ostringstream s;
    s << ", interior vertices jittered by " << jitter << " (seed " << seed << ")";
    description += s.str();
  }
  return std::make_shared<const ws4::Ws4Space>(std::move(mesh), description, extent);
}

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
