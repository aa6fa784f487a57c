#include "spaces/tmesh/sections_from_config.hpp"

#include <algorithm>
#include <numbers>

#include "spaces/tmesh/refinement_targets.hpp"

namespace iga {

namespace {

/// The scalar or the two items of a `[x, y]` list; `what` names it in messages.
std::vector<ConfigNode> per_direction(const ConfigNode& node, const std::string& what) {
  std::vector<ConfigNode> items = node.is_sequence() ? node.items() : std::vector<ConfigNode>{node, node};
  if (items.size() != 2) node.fail("expected one " + what + " or [" + what + " in x, " + what + " in y]");
  return items;
}

/// The (x, y) section spaces named by the `section` and `frequency` keys of `node`, with this n.
std::array<SectionSpec, 2> section_pair_from_config(const ConfigNode& node, int n) {
  std::array<SectionSpec, 2> spec;
  if (auto sn = node.find("section")) {
    const std::vector<ConfigNode> items = per_direction(*sn, "family");
    for (int d = 0; d < 2; ++d) {
      const std::string family = items[d].as_choice({"poly", "trig", "hyperbolic"});
      spec[d].family = family == "trig" ? SectionFamily::trigonometric
                       : family == "hyperbolic" ? SectionFamily::hyperbolic
                                                : SectionFamily::polynomial;
    }
  }
  if (auto wn = node.find("frequency")) {
    const std::vector<ConfigNode> items = per_direction(*wn, "frequency");
    for (int d = 0; d < 2; ++d) {
      spec[d].w = items[d].as_double();
      if (!(spec[d].w > 0.0)) items[d].fail("the frequency must be > 0 (got " + format_number(spec[d].w) + ")");
    }
  }
  for (SectionSpec& s : spec) s.n = n;
  return spec;
}

}  // namespace

TMesh with_sections_from_config(const TMesh& mesh, const ConfigNode& space, int n) {
  std::vector<std::array<SectionSpec, 2>> pair(mesh.num_cells(), section_pair_from_config(space, n));
  if (auto regions = space.find("sections_in")) {
    for (const ConfigNode& region : regions->items()) {
      region.check_keys({"box", "section", "frequency"});
      const ConfigNode box = region["box"];
      const std::vector<ConfigNode> corners = box.items();
      if (corners.size() != 2) box.fail("expected a box [[x0, y0], [x1, y1]]");
      RefinementTarget target{RefinementTarget::Kind::box, {corners[0].as_point(), corners[1].as_point()}};
      if (!(target.points[0].array() < target.points[1].array()).all())
        box.fail("expected a box [[x0, y0], [x1, y1]] with x0 < x1 and y0 < y1");
      const std::vector<int> cells = cells_meeting(mesh, target);
      if (cells.empty()) box.fail("no base cell overlaps this box");
      const std::array<SectionSpec, 2> spec = section_pair_from_config(region, n);
      for (int c : cells) pair[c] = spec;
    }
  }
  // Distinct section spaces, and the cells' indices into them.
  std::vector<SectionSpec> sections;
  auto index_of = [&](const SectionSpec& s) {
    auto it = std::find(sections.begin(), sections.end(), s);
    if (it != sections.end()) return static_cast<int>(it - sections.begin());
    sections.push_back(s);
    return static_cast<int>(sections.size()) - 1;
  };
  std::vector<std::array<int, 2>> indices(pair.size());
  for (std::size_t c = 0; c < pair.size(); ++c) indices[c] = {index_of(pair[c][0]), index_of(pair[c][1])};
  return mesh.with_sections(indices, std::move(sections));
}

void check_trigonometric_cells(const TMesh& mesh, const ConfigNode& space) {
  double worst = 0.0, w_worst = 0.0, h_worst = 0.0;
  for (int c = 0; c < mesh.num_cells(); ++c) {
    const TCell& cell = mesh.cells()[c];
    for (int d = 0; d < 2; ++d) {
      const SectionSpec& s = mesh.sections()[d == 0 ? cell.section_s : cell.section_t];
      const double h = d == 0 ? mesh.width(c) : mesh.height(c);
      if (s.family == SectionFamily::trigonometric && s.w * h > worst) worst = s.w * h, w_worst = s.w, h_worst = h;
    }
  }
  if (worst < std::numbers::pi) return;
  const std::string msg = "trigonometric sections need w*h < pi on every cell: w = " + format_number(w_worst) +
                          " on a cell side h = " + format_number(h_worst) + " gives w*h = " + format_number(worst) +
                          "; use more elements, a higher level or a lower frequency";
  if (auto wn = space.find("frequency")) wn->fail(msg);
  space.fail(msg);
}

}  // namespace iga
