#include "config/config_node.hpp"
#include "spaces/tmesh/tmesh_from_config.hpp"

#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "spaces/space_catalogue.hpp"
#include "spaces/tmesh/refine_near_from_config.hpp"
#include "spaces/tmesh/sections_from_config.hpp"
#include "spaces/tmesh/tmesh_space.hpp"

namespace iga {

SpacePtr make_tmesh_space(const ConfigNode& domain, const ConfigNode& space, int level) {
  space.check_keys({"type", "section", "n", "regularity", "frequency", "elements", "refine", "refine_near", "sections_in"});
  const ConfigNode nn = space["n"];
  const int n = nn.as_int();
  if (n < 2) nn.fail("section spaces need n >= 2 (got " + std::to_string(n) + ")");
  // n − 2 is the degree of the section spaces' polynomial part: past this their Hermite
  // interpolation is hopelessly ill-conditioned in double precision.
  constexpr int kMaxSectionDimension = 24;
  if (n > kMaxSectionDimension)
    nn.fail("section spaces of dimension n > " + std::to_string(kMaxSectionDimension) + " are not supported (got " +
            std::to_string(n) + ")");
  int r = (n - 1) / 2;
  if (auto rn = space.find("regularity")) {
    r = rn->as_int();
    if (r < 0 || n < 2 * r + 1)
      rn->fail("regularity must be between 0 and (n-1)/2 = " + std::to_string((n - 1) / 2) +
               " so that n >= 2r+1 (got " + std::to_string(r) + ")");
  }
  std::vector<int> elements{2, 2};
  if (auto en = space.find("elements")) {
    elements = en->as_ints();
    if (elements.size() != 2) en->fail("expected [nx, ny] (got " + std::to_string(elements.size()) + " numbers)");
    if (elements[0] < 1 || elements[1] < 1) en->fail("element counts must be >= 1");
  }
  if (level < 0 || level > 12) space.fail("refinement level must be in 0..12 (got " + std::to_string(level) + ")");

  const std::string type = domain["type"].as_choice({"rectangle", "l_shape"});
  domain.check_keys({"type", "min", "max"});
  const Eigen::Vector2d lo = domain["min"].as_point(), hi = domain["max"].as_point();
  if (!(lo.x() < hi.x()) || !(lo.y() < hi.y())) domain["max"].fail("max must be greater than min in both coordinates");
  if (type == "l_shape" && (elements[0] % 2 || elements[1] % 2))
    space.fail("an l_shape domain needs even element counts (the removed quarter must be whole cells)");
  TMesh mesh = with_sections_from_config(type == "rectangle" ? TMesh::rectangle(lo, hi, elements[0], elements[1], SectionSpec{})
                                                             : TMesh::l_shape(lo, hi, elements[0], elements[1], SectionSpec{}),
                                         space, n);
  if (auto rn = space.find("refine")) {
    // Boxes select cells by their coordinates only: refine the cells, build the topology once.
    std::vector<TCell> cells = mesh.cells();
    const double X = double(mesh.bound(1) - mesh.bound(0)), Y = double(mesh.bound(3) - mesh.bound(2));
    for (const ConfigNode& box : rn->items()) {
      const std::vector<double> b = box.as_doubles();
      if (b.size() != 4) box.fail("expected a box [x0, y0, x1, y1] relative to the domain (got " + std::to_string(b.size()) + " numbers)");
      std::vector<int> inside;
      for (int c = 0; c < static_cast<int>(cells.size()); ++c) {
        const TCell& cell = cells[c];
        const double x0 = (cell.x0 - mesh.bound(0)) / X, x1 = (cell.x1 - mesh.bound(0)) / X;
        const double y0 = (cell.y0 - mesh.bound(2)) / Y, y1 = (cell.y1 - mesh.bound(2)) / Y;
        const double eps = 1e-12;
        if (x0 >= b[0] - eps && x1 <= b[2] + eps && y0 >= b[1] - eps && y1 <= b[3] + eps) inside.push_back(c);
      }
      if (inside.empty()) box.fail("no cell lies inside this box");
      cells = TMesh::split_cells(cells, inside);
    }
    mesh = TMesh(std::move(cells), mesh.sections(), mesh.point(0, 0), mesh.unit());
  }
  if (auto rn = space.find("refine_near")) mesh = refine_near_from_config(std::move(mesh), *rn);
  for (int l = 0; l < level; ++l) mesh = mesh.refined_uniformly();
  if (!mesh.admissibility_problem().empty()) space.fail("the refined T-mesh is not admissible: " + mesh.admissibility_problem());
  check_trigonometric_cells(mesh, space);
  const std::string desc = type + " [" + format_number(lo.x()) + ", " + format_number(hi.x()) + "] x [" + format_number(lo.y()) + ", " + format_number(hi.y()) + "]";
  try {
    return std::make_shared<const TMeshSpace>(std::move(mesh), r, type == "rectangle", desc);
  } catch (const std::invalid_argument& e) {
    space.fail(e.what());
  }
}

SpaceCatalogueEntry tmesh_catalogue_entry() {
  // ../shared/notes/tmesh-generalized-splines.md: sections <1, s, ..., s^(n-2), u(s), v(s)>, C^r with n >= 2r+1.
  return {"tmesh",
          "generalized splines on T-meshes, sections <1, s, ..., s^(n-2), u, v> (poly, trig, hyperbolic), "
          "C^r with 0 <= r <= (n-1)/2 (default (n-1)/2); local refinement",
          {{"rectangle", "min: [x, y], max: [x, y]", "", {}},
           {"l_shape", "min: [x, y], max: [x, y] (the box without its upper-right quarter)", "", {}}}};
}

}  // namespace iga
