#include "spaces/ws4/ws4_from_config.hpp"

#include <sstream>

#include "spaces/ws4/ws4_jitter.hpp"
#include "spaces/ws4/ws4_space.hpp"

namespace iga {

namespace {

std::string box(const Point2& lo, const Point2& hi) {
  std::ostringstream s;
  s << "[" << lo.x() << ", " << hi.x() << "] x [" << lo.y() << ", " << hi.y() << "]";
  return s.str();
}

}  // namespace

SpacePtr make_ws4_space(const ConfigNode& domain, const ConfigNode& space, int level) {
  space.check_keys({"type", "elements"});
  if (space.has("type")) space["type"].as_choice({"ws4"});
  int nx = 2, ny = 2;
  if (const auto en = space.find("elements")) {
    if (en->is_sequence()) {
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
  if (level < 0 || level > 12) space.fail("refinement level must be in 0..12 (got " + std::to_string(level) + ")");

  const std::string type = domain["type"].as_choice({"unit_square", "rectangle"});
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
  ws4::Triangulation mesh = ws4::Triangulation::rectangle(nx, ny, lo, hi);
  for (int l = 0; l < level; ++l) mesh = mesh.refined();
  std::string description = "rectangle " + box(lo, hi) + ", " + std::to_string(nx) + "x" + std::to_string(ny) + " squares";
  if (const auto jn = domain.find("jitter")) {
    const double jitter = jn->as_double();
    if (!(jitter >= 0.0 && jitter <= 0.2)) jn->fail("jitter must be in [0, 0.2] (fraction of the shortest edge)");
    const int seed = domain.has("seed") ? domain["seed"].as_int() : 1;
    // Each level is jittered afresh from the regular refinement (seed + level: reproducible).
    ws4::jitter_interior_vertices(mesh, jitter, static_cast<unsigned>(seed + level));
    std::ostringstream s;
    s << ", interior vertices jittered by " << jitter << " (seed " << seed << ")";
    description += s.str();
  }
  return std::make_shared<const ws4::Ws4Space>(std::move(mesh), description);
}

}  // namespace iga
