#include "spaces/g1_4split/g1_4split_from_config.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "config/config_file_path.hpp"
#include "config/errors.hpp"
#include "geometry/exact_surface.hpp"
#include "mesh/read_quad_surface_mesh.hpp"
#include "mesh/validate_quad_surface.hpp"
#include "spaces/g1/g1_from_config.hpp"
#include "spaces/g1/multipatch_domains.hpp"
#include "spaces/g1_4split/g1_4split_meshes.hpp"
#include "spaces/g1_4split/line_gluing.hpp"
#include "spaces/g1_4split/g1_4split_space.hpp"
#include "spaces/g1_4split/g1_4split_surface_space.hpp"
#include "spaces/g1_4split/open_quad_surfaces.hpp"
#include "spaces/space_catalogue.hpp"

namespace iga {

namespace {

/// The built-in surfaces: closed, then open.
std::vector<std::string> g14_surface_names() {
  std::vector<std::string> names = {"cube", "split_tetrahedron"};
  for (const std::string& n : open_quad_surface_names()) names.push_back(n);
  return names;
}

/// Builds the space with `build(options)`; if the degree is below the separability degree, fails
/// at `degree_node` naming `what` and the smallest degree (up to 10) that works.
template <class Build>
SpacePtr build_or_name_the_separable_degree(const G14Options& o, const ConfigNode& degree_node, const std::string& what,
                                           int level, const Build& build) {
  try {
    return build(o);
  } catch (const NotSeparable& e) {
    int works = -1;
    for (int k = o.degree + 1; k <= 10 && works < 0; ++k) {
      G14Options t = o;
      t.degree = k;
      try {
        build(t);
        works = k;
      } catch (const NotSeparable&) {
      } catch (const InputError&) {
        works = k;
      }
    }
    degree_node.fail("g1_4split degree " + std::to_string(o.degree) + " is below the separability degree of " + what +
                     " at level " + std::to_string(level) + " (" + e.what() + "); the smallest degree that works is " +
                     (works > 0 ? std::to_string(works) : std::string("above 10")));
  }
}

/// A quad surface in 3D, closed or open: a built-in (cube, split_tetrahedron, or one of
/// open_quad_surfaces.hpp) or a quad .obj/.off file.
std::pair<QuadTopology, std::vector<Eigen::Vector3d>> surface_mesh(const ConfigNode& domain) {
  domain.check_keys({"type", "mesh", "file", "fit_onto"});
  const bool builtin = domain.has("mesh"), file = domain.has("file");
  if (builtin == file)
    domain.fail("give either 'mesh' (a built-in surface) or 'file' (a quad mesh in .obj or .off), not both");
  if (builtin) {
    const std::string name = domain["mesh"].as_choice(g14_surface_names());
    if (name == "cube") return {cube_topology(), cube_vertices()};
    if (name == "split_tetrahedron") return {split_tetrahedron_topology(), split_tetrahedron_vertices()};
    return open_quad_surface(name);
  }
  const ConfigNode node = domain["file"];
  const std::filesystem::path path = resolve_config_file(node);
  const QuadSurfaceFile read = node.guard([&] {
    QuadSurfaceFile file = read_quad_surface_mesh(path.string());
    validate_quad_surface(file);  // degenerate, folded, repeated faces: named here, not as a failed solve
    return file;
  });
  QuadTopology topology =
      node.guard([&] { return QuadTopology(static_cast<int>(read.points.size()), read.quads, read.source); });
  for (int v = 0; v < topology.num_vertices(); ++v)
    if (topology.vertex_faces(v) == 0) node.fail(read.source + ": vertex " + std::to_string(v + 1) + " is in no face");
  return {std::move(topology), read.points};
}

/// Three finite numbers [x, y, z].
Eigen::Vector3d vector3(const ConfigNode& node, const std::string& what) {
  const std::vector<double> v = node.is_sequence() ? node.as_doubles() : std::vector<double>{};
  if (v.size() != 3 || !std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2]))
    node.fail(what + " is a list of three finite numbers [x, y, z]");
  return {v[0], v[1], v[2]};
}

/// domain.fit_onto: {shape: sphere, radius: R, center: [x, y, z]} or {shape: cylinder, radius: R,
/// axis: [x, y, z], center: a point of the axis}; every vertex of the mesh must lie on it (to 1e-6 R).
ExactSurface fit_onto(const ConfigNode& node, const std::vector<Eigen::Vector3d>& vertices, const std::string& mesh) {
  node.check_keys({"shape", "radius", "center", "axis"});
  ExactSurface s;
  s.shape = node["shape"].as_choice({"sphere", "cylinder"}) == "sphere" ? ExactSurface::Shape::sphere
                                                                       : ExactSurface::Shape::cylinder;
  s.radius = node["radius"].as_double();
  if (!(s.radius > 0 && std::isfinite(s.radius))) node["radius"].fail("radius must be a number > 0");
  if (const auto c = node.find("center")) s.center = vector3(*c, "center");
  if (const auto a = node.find("axis")) {
    if (s.shape == ExactSurface::Shape::sphere) a->fail("a sphere has no axis (axis is for shape: cylinder)");
    s.axis = vector3(*a, "axis");
    if (!(s.axis.norm() > 0)) a->fail("the axis must not be zero");
    s.axis.normalize();
  }
  for (std::size_t v = 0; v < vertices.size(); ++v)
    if (const double d = s.distance(vertices[v]); !(std::abs(d) <= 1e-6 * s.radius))
      node.fail("vertex " + std::to_string(v + 1) + " of " + mesh + " is " + format_number(d) + " from the " +
                s.describe() + " (more than 1e-6 of its radius): the mesh's vertices must lie on the surface "
                "its faces are fitted onto");
  return s;
}

/// The linear blending has a'(γ) ≠ 0: refused where an interior crossing vertex sees different
/// slopes on opposite edges (the twist compatibility of the gluing fails there).
void check_linear_blending(const ConfigNode& space, const QuadTopology& topology, const std::vector<SplitGluing>& gluing) {
  const int v = twist_incompatible_vertex(topology, gluing);
  if (v >= 0)
    space["blending"].fail("blending linear is refused on '" + topology.name() + "': vertex " + std::to_string(v) +
                           " is an interior valence-4 (crossing) vertex between vertices of different gluing values, "
                           "where linear gluing data have slopes the twists cannot follow; use lines (the default) there");
}

PatchMesh domain_mesh(const ConfigNode& domain) {
  const std::string type = domain["type"].as_choice({"multipatch", "mesh_file", "surface"});
  if (type == "multipatch") {
    domain.check_keys({"type", "name"});
    std::vector<std::string> names = g14_domain_names();
    for (const std::string& n : multipatch_domain_names()) names.push_back(n);
    const std::string name = domain["name"].as_choice(names);
    const auto own = g14_domain_names();
    return std::find(own.begin(), own.end(), name) != own.end() ? g14_domain(name) : multipatch_domain(name);
  }
  return patch_mesh_from_config(domain);
}

}  // namespace

std::vector<SpaceRequestSize> g1_4split_requested_sizes(const ConfigNode& domain, const ConfigNode& space, int levels) {
  try {
    const auto type = domain.is_map() ? domain.find("type") : std::nullopt;
    const auto file = domain.is_map() ? domain.find("file") : std::nullopt;
    const auto degree = space.find("degree");
    if (!type || !type->is_scalar() || type->as_string() != "surface" || !file || !file->is_scalar() || !degree ||
        !degree->is_scalar())
      return {};
    const double k = degree->as_int();
    const auto regularity = space.find("regularity");
    const double r = regularity ? regularity->as_int() : 1;
    if (k < 3 || k > 10 || r < 1 || 2 * k - r < 4) return {};
    // Reading the file is cheap (its size is capped); the space built on it is not.
    const QuadSurfaceFile read = read_quad_surface_mesh(resolve_config_file(*file).string());
    std::vector<std::pair<int, int>> edges;
    std::vector<int> used;
    for (const auto& q : read.quads)
      for (int c = 0; c < 4; ++c) {
        edges.emplace_back(std::min(q[c], q[(c + 1) % 4]), std::max(q[c], q[(c + 1) % 4]));
        used.push_back(q[c]);
      }
    std::sort(edges.begin(), edges.end());
    std::sort(used.begin(), used.end());
    double faces = static_cast<double>(read.quads.size());
    double num_edges = static_cast<double>(std::unique(edges.begin(), edges.end()) - edges.begin());
    double vertices = static_cast<double>(std::unique(used.begin(), used.end()) - used.begin());
    const double inner = (2 * k - r - 3) * (2 * k - r - 3) + 4, per_edge = 4 * k - 2 * r - 6;
    const double active = inner + 4 * per_edge + 16, coefficients = (2 * k - r + 1) * (2 * k - r + 1);
    // Building level 0 (the surface fit) takes about 64 N² bytes per face; a nested level keeps that
    // fit and builds only the refined basis, about 8 N² per face (6 N² measured on the 8 x 4 torus
    // at levels 3 and 4, k = 5: 124 and 491 MB).
    const double level0_bytes = 64.0 * coefficients * coefficients * faces;
    std::vector<SpaceRequestSize> sizes;
    for (int level = 0; level < levels; ++level) {
      SpaceRequestSize size;
      size.elements = faces;
      size.dofs = faces * inner + num_edges * per_edge + 4 * vertices;
      size.element_entries = faces * active * active;
      size.build_bytes = level == 0 ? level0_bytes : level0_bytes + 8.0 * coefficients * coefficients * faces;
      size.basis = "the " + std::to_string(read.quads.size()) + " faces of domain.file and space.degree";
      size.blame = *file;
      sizes.push_back(size);
      // One split: a new vertex on every edge and in every face; every edge halved, four new per face.
      vertices += num_edges + faces;
      num_edges = 2 * num_edges + 4 * faces;
      faces *= 4;
    }
    return sizes;
  } catch (const InputError&) {
    return {};  // the builder reports it, in its own order
  }
}

SpacePtr make_g1_4split_space(const ConfigNode& domain, const ConfigNode& space, int level, SpaceExtent extent) {
  space.check_keys({"type", "degree", "regularity", "blending", "refinement", "geometry_fit"});
  G14Options o;
  o.extent = extent;
  const ConfigNode dn = space["degree"];
  o.degree = dn.as_int();
  if (o.degree < 3 || o.degree > 10) dn.fail("g1_4split degree must be in 3..10 (got " + std::to_string(o.degree) + ")");
  if (space.has("regularity")) {
    o.regularity = space["regularity"].as_int();
    if (o.regularity < 1 || 2 * o.degree - o.regularity < 4)
      space["regularity"].fail("g1_4split regularity must be >= 1 (C1 across the split lines) and <= 2k - 4 (got " +
                               std::to_string(o.regularity) + ")");
  }
  if (space.has("blending")) {
    const std::string b = space["blending"].as_choice({"lines", "q1", "c1", "linear", "q0"});
    if (b == "q0")
      space["blending"].fail(
          "blending q0 (the paper's C0 blending) is refused for analysis: with it every function of the space has a "
          "zero tangential derivative at the midpoint of each edge between vertices of different gluing values, so "
          "every geometry is singular there; use lines (the default), q1 or c1");
    o.blending = blending_from_name(b);
  }
  if (space.has("refinement")) o.nested = space["refinement"].as_choice({"nested", "rebuild"}) == "nested";
  // The fair map is the default with the default gluing; the other blendings keep the
  // least-squares map their tables were measured with (docs/spaces/g1_4split.md).
  o.fit = o.blending == Blending::lines ? GeometryFit::fair : GeometryFit::least_squares;
  o.fit_required = space.has("geometry_fit");
  if (space.has("geometry_fit"))
    o.fit = space["geometry_fit"].as_choice({"fair", "least_squares"}) == "fair" ? GeometryFit::fair
                                                                                : GeometryFit::least_squares;
  if (level < 0 || level > 6) space.fail("refinement level must be in 0..6 (got " + std::to_string(level) + ")");
  o.level = level;
  if (domain["type"].as_choice({"multipatch", "mesh_file", "surface"}) == "surface") {
    if (space.has("geometry_fit") && o.fit == GeometryFit::fair)
      space["geometry_fit"].fail(
          "geometry_fit fair is planar only (it keeps the boundary on the mesh's straight segments); a g1_4split "
          "surface is fitted by least squares");
    if (!o.nested)
      space["refinement"].fail(
          "a g1_4split surface is refined nested only (rebuilding would fit a different surface at every level)");
    const auto [topology, vertices] = surface_mesh(domain);
    // fit_onto: the facets mapped onto the exact surface before the fit (a small hook in fit_surface).
    FitTarget onto;
    std::string onto_name;
    if (const auto node = domain.find("fit_onto")) {
      const ExactSurface exact = fit_onto(*node, vertices, "'" + topology.name() + "'");
      onto = [exact](const Eigen::Vector3d& p) { return exact.closest(p); };
      onto_name = exact.describe();
    }
    if (o.blending == Blending::linear) check_linear_blending(space, topology, symmetric_gluing(topology, o.blending));
    return build_or_name_the_separable_degree(o, dn, "the surface '" + topology.name() + "'", level,
                                              [&](const G14Options& t) -> SpacePtr {
                                                return domain.guard([&] {
                                                  return std::make_shared<const G14SurfaceSpace>(topology, vertices, t,
                                                                                                 onto, onto_name);
                                                });
                                              });
  }
  const PatchMesh mesh = domain_mesh(domain);
  const QuadTopology topology = domain.guard([&] { return quad_topology(mesh); });
  if (o.blending == Blending::linear) check_linear_blending(space, topology, symmetric_gluing(topology, o.blending, vertex_angles(mesh)));
  return build_or_name_the_separable_degree(o, dn, "'" + mesh.name() + "'", level, [&](const G14Options& t) -> SpacePtr {
    return domain.guard([&] { return std::make_shared<const G14Space>(mesh, t); });
  });
}

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
           {"surface", "a smooth surface in 3D from a quad mesh, closed or open: mesh, or file: .obj, .off", "mesh",
            g14_surface_names()}}};
}

}  // namespace iga
