#include "spaces/tmesh/refine_near_from_config.hpp"

#include <muParser.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "spaces/tmesh/refinement_targets.hpp"
#include "spaces/tmesh/tmesh_refinement.hpp"

namespace iga {

namespace {

/// The polyline through `samples` points (x(t), y(t)) at equispaced t in [t0, t1].
std::vector<Eigen::Vector2d> sample_curve(const ConfigNode& curve) {
  curve.check_keys({"x", "y", "t", "samples"});
  const std::vector<double> range = curve["t"].as_doubles();
  if (range.size() != 2 || !(range[0] < range[1])) curve["t"].fail("expected a parameter range [t0, t1] with t0 < t1");
  int samples = 512;
  if (auto s = curve.find("samples")) {
    samples = s->as_int();
    if (samples < 2 || samples > 100000) s->fail("samples must be between 2 and 100000");
  }
  double t = 0.0;
  mu::Parser px, py;
  for (auto [parser, key] : {std::pair{&px, "x"}, std::pair{&py, "y"}}) {
    const ConfigNode node = curve[key];
    try {
      parser->DefineVar("t", &t);
      parser->DefineConst("pi", std::numbers::pi);
      parser->SetExpr(node.as_string());
      parser->Eval();  // reports syntax errors and unknown names now
    } catch (const mu::Parser::exception_type& e) {
      node.fail("cannot evaluate '" + node.as_string() + "' as an expression in t: " + e.GetMsg());
    }
  }
  std::vector<Eigen::Vector2d> out;
  for (int k = 0; k < samples; ++k) {
    t = range[0] + (range[1] - range[0]) * k / (samples - 1);
    const Eigen::Vector2d p(px.Eval(), py.Eval());
    if (!p.allFinite()) curve.fail("the curve is not finite at t = " + format_number(t));
    out.push_back(p);
  }
  return out;
}

RefinementTarget parse_target(const ConfigNode& entry) {
  RefinementTarget target;
  int given = 0;
  if (auto p = entry.find("point")) {
    ++given;
    target.kind = RefinementTarget::Kind::point;
    target.points = {p->as_point()};
  }
  if (auto b = entry.find("box")) {
    ++given;
    target.kind = RefinementTarget::Kind::box;
    const std::vector<ConfigNode> corners = b->items();
    if (corners.size() != 2) b->fail("expected a box [[x0, y0], [x1, y1]]");
    target.points = {corners[0].as_point(), corners[1].as_point()};
    if (!(target.points[0].array() < target.points[1].array()).all())
      b->fail("expected a box [[x0, y0], [x1, y1]] with x0 < x1 and y0 < y1 (lower-left, then upper-right corner)");
  }
  if (auto c = entry.find("curve")) {
    ++given;
    target.kind = RefinementTarget::Kind::polyline;
    target.points = sample_curve(*c);
  }
  if (given != 1) entry.fail("expected exactly one of point, box or curve");
  return target;
}

}  // namespace

TMesh refine_near_from_config(TMesh mesh, const ConfigNode& refine_near) {
  if (!refine_near.is_sequence()) refine_near.fail("expected a list of {point|box|curve: ..., times: k}");
  for (const ConfigNode& entry : refine_near.items()) {
    if (!entry.is_map()) entry.fail("expected {point|box|curve: ..., times: k}");
    entry.check_keys({"point", "box", "curve", "times"});
    const RefinementTarget target = parse_target(entry);
    int times = 1;
    if (auto t = entry.find("times")) {
      times = t->as_int();
      if (times < 1 || times > 20) t->fail("times must be between 1 and 20 (got " + std::to_string(times) + ")");
    }
    for (int k = 0; k < times; ++k) {
      const std::vector<int> cells = cells_meeting(mesh, target);
      if (cells.empty()) entry.fail("no cell of the T-mesh meets this target (is it inside the domain?)");
      try {
        mesh = refine_admissibly(mesh, cells);
      } catch (const std::runtime_error& e) {
        entry.fail(std::string("cannot refine ") + std::to_string(times) + " times here: " + e.what());
      }
    }
  }
  return mesh;
}

}  // namespace iga
