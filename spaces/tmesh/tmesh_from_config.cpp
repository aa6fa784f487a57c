#include "solver/config_node.hpp"
#include "spaces/tmesh/tmesh_from_config.hpp"

#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "spaces/tmesh/refine_near_from_config.hpp"
#include "spaces/tmesh/tmesh_space.hpp"

namespace iga {

namespace {

/// `mesh` with section space `s` along x and `t` along y on every cell.
TMesh with_sections(const TMesh& mesh, const SectionSpec& s, const SectionSpec& t) {
  std::vector<TCell> cells = mesh.cells();
  for (TCell& c : cells) c.section_s = 0, c.section_t = 1;
  return TMesh(std::move(cells), {s, t}, mesh.point(0, 0), mesh.unit());
}

}  // namespace

SpacePtr make_tmesh_space(const ConfigNode& domain, const ConfigNode& space, int level) {
  space.check_keys({"type", "section", "n", "regularity", "frequency", "elements", "refine", "refine_near"});
  // One section space per direction (s along x, t along y): `section: trig` or `section: [trig, poly]`.
  SectionSpec spec[2];
  if (auto sn = space.find("section")) {
    const std::vector<ConfigNode> items = sn->is_sequence() ? sn->items() : std::vector<ConfigNode>{*sn, *sn};
    if (items.size() != 2) sn->fail("expected one section family or [family in x, family in y]");
    for (int d = 0; d < 2; ++d) {
      const std::string family = items[d].as_choice({"poly", "trig", "hyperbolic"});
      spec[d].family = family == "trig" ? SectionFamily::trigonometric
                       : family == "hyperbolic" ? SectionFamily::hyperbolic
                                                : SectionFamily::polynomial;
    }
  }
  const ConfigNode nn = space["n"];
  const int n = nn.as_int();
  if (n < 2) nn.fail("section spaces need n >= 2 (got " + std::to_string(n) + ")");
  int r = (n - 1) / 2;
  if (auto rn = space.find("regularity")) {
    r = rn->as_int();
    if (r < 0 || n < 2 * r + 1)
      rn->fail("regularity must be between 0 and (n-1)/2 = " + std::to_string((n - 1) / 2) +
               " so that n >= 2r+1 (got " + std::to_string(r) + ")");
  }
  if (auto wn = space.find("frequency")) {
    const std::vector<ConfigNode> items = wn->is_sequence() ? wn->items() : std::vector<ConfigNode>{*wn, *wn};
    if (items.size() != 2) wn->fail("expected one frequency or [frequency in x, frequency in y]");
    for (int d = 0; d < 2; ++d) {
      spec[d].w = items[d].as_double();
      if (!(spec[d].w > 0.0)) items[d].fail("the frequency must be > 0 (got " + format_number(spec[d].w) + ")");
    }
  }
  for (SectionSpec& sp : spec) sp.n = n;
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
  TMesh mesh = type == "rectangle" ? TMesh::rectangle(lo, hi, elements[0], elements[1], spec[0])
                                   : TMesh::l_shape(lo, hi, elements[0], elements[1], spec[0]);
  if (!(spec[0] == spec[1])) mesh = with_sections(mesh, spec[0], spec[1]);
  if (auto rn = space.find("refine")) {
    for (const ConfigNode& box : rn->items()) {
      const std::vector<double> b = box.as_doubles();
      if (b.size() != 4) box.fail("expected a box [x0, y0, x1, y1] relative to the domain (got " + std::to_string(b.size()) + " numbers)");
      std::vector<int> inside;
      for (int c = 0; c < mesh.num_cells(); ++c) {
        const TCell& cell = mesh.cells()[c];
        const double X = double(mesh.bound(1) - mesh.bound(0)), Y = double(mesh.bound(3) - mesh.bound(2));
        const double x0 = (cell.x0 - mesh.bound(0)) / X, x1 = (cell.x1 - mesh.bound(0)) / X;
        const double y0 = (cell.y0 - mesh.bound(2)) / Y, y1 = (cell.y1 - mesh.bound(2)) / Y;
        const double eps = 1e-12;
        if (x0 >= b[0] - eps && x1 <= b[2] + eps && y0 >= b[1] - eps && y1 <= b[3] + eps) inside.push_back(c);
      }
      if (inside.empty()) box.fail("no cell lies inside this box");
      mesh = mesh.refined(inside);
    }
  }
  if (auto rn = space.find("refine_near")) mesh = refine_near_from_config(std::move(mesh), *rn);
  for (int l = 0; l < level; ++l) mesh = mesh.refined_uniformly();
  if (!mesh.admissibility_problem().empty()) space.fail("the refined T-mesh is not admissible: " + mesh.admissibility_problem());
  // w h < pi for trigonometric sections, per direction (s: cell widths, t: cell heights).
  for (int d = 0; d < 2; ++d) {
    if (spec[d].family != SectionFamily::trigonometric) continue;
    double hmax = 0.0;
    for (int c = 0; c < mesh.num_cells(); ++c) hmax = std::max(hmax, d == 0 ? mesh.width(c) : mesh.height(c));
    if (spec[d].w * hmax >= std::numbers::pi) {
      const std::string msg = "trigonometric sections need w*h < pi on every cell: w = " + format_number(spec[d].w) +
                              ", largest cell side h = " + format_number(hmax) + " gives w*h = " +
                              format_number(spec[d].w * hmax) + "; use more elements, a higher level or a lower frequency";
      if (auto wn = space.find("frequency")) wn->fail(msg);
      space.fail(msg);
    }
  }
  const std::string desc = type + " [" + format_number(lo.x()) + ", " + format_number(hi.x()) + "] x [" + format_number(lo.y()) + ", " + format_number(hi.y()) + "]";
  try {
    return std::make_shared<const TMeshSpace>(std::move(mesh), r, type == "rectangle", desc);
  } catch (const std::invalid_argument& e) {
    space.fail(e.what());
  }
}

}  // namespace iga
