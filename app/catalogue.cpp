#include "app/catalogue.hpp"

#include <sstream>
#include <utility>
#include <vector>

#include "spaces/space_factory.hpp"

namespace iga {

namespace {

using Entries = std::vector<std::pair<std::string, std::string>>;

// The command line may not look into the spaces' folders, so the descriptions live here; the
// names of space types come from the registry (a type missing here is listed without description).
const Entries space_descriptions = {
    {"bspline", "tensor-product B-splines of any degree and regularity on a rectangle, annulus or patch"},
    {"ws4", "C1 quartic Wang-Shi macro-elements on triangulations (unit_square, rectangle, l_shape, polygon, mesh_file)"},
    {"tmesh", "C1 (or C0) splines on T-meshes with local refinement; polynomial or generalized sections"},
    {"g1", "G1-smooth multi-patch splines on quadrilateral/triangle patches (multipatch, mesh_file)"},
    {"g1_4split", "G1 macro-patches on 4-split quadrilaterals (multipatch, mesh_file)"},
    {"surface", "G1 Bernstein triangles on a smooth surface in 3D (Laplace-Beltrami problems)"},
};

const Entries domain_types = {
    {"rectangle", "axis-parallel rectangle, min: [x, y], max: [x, y] (bspline, ws4, tmesh)"},
    {"unit_square", "[0,1]^2 (ws4)"},
    {"quarter_annulus", "a quarter annulus, exact (NURBS) geometry (bspline)"},
    {"patch", "one B-spline or NURBS patch from control points (bspline)"},
    {"l_shape", "an L-shaped domain (ws4, tmesh)"},
    {"polygon", "a polygon, optionally with holes, triangulated (ws4)"},
    {"multipatch", "a built-in multi-patch mesh, name: one of the meshes below (g1, g1_4split)"},
    {"mesh_file", "a mesh file: .msh/.geo (Gmsh), .obj, .off (ws4, g1, g1_4split)"},
    {"surface", "a triangulated surface in 3D, built-in mesh: or file: (surface)"},
};

const Entries builtin_meshes = {
    {"3p_square, 5p_square", "multipatch: the unit square in 3 / 5 quadrilateral patches"},
    {"pentagon, 5p_pentagon", "multipatch: a pentagon around one extraordinary vertex"},
    {"3p_hexagon", "multipatch: a hexagon in 3 patches"},
    {"lshape_8p", "multipatch: an L-shape in 8 patches"},
    {"4t_crisscross, 4t_star, 2q2t_square", "multipatch: triangle and mixed patch layouts"},
    {"fan3, fan5, fan6, grid2x2, halffan3", "multipatch (g1_4split): fans of quadrilaterals around one vertex"},
    {"icosphere (level:), octahedron, tetrahedron", "surface: closed triangle meshes of the unit sphere"},
    {"perturbed_octahedron, height_field", "surface: a non-spherical closed surface, an open height field"},
};

void section(std::ostringstream& out, const std::string& title, const Entries& entries) {
  out << title << ":\n";
  for (const auto& [name, text] : entries) {
    out << "  " << name;
    out << std::string(name.size() < 44 ? 44 - name.size() : 1, ' ') << text << '\n';
  }
}

}  // namespace

std::string catalogue_text() {
  Entries spaces;
  for (const std::string& type : space_types()) {
    std::string text = "(no description)";
    for (const auto& [name, description] : space_descriptions)
      if (name == type) text = description;
    spaces.emplace_back(type, text);
  }
  std::ostringstream out;
  section(out, "space types (space.type)", spaces);
  section(out, "domain types (domain.type)", domain_types);
  section(out, "built-in meshes (domain.name / domain.mesh)", builtin_meshes);
  return out.str();
}

}  // namespace iga
