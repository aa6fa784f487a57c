#include "spaces/graph/graph_from_config.hpp"

#include <cmath>
#include <vector>

#include "config/errors.hpp"
#include "config/expression.hpp"
#include "spaces/graph/graph_surface_space.hpp"

namespace iga {

namespace {

/// Domain types that are not planar: the surfaces in 3D, and a graph again.
bool is_surface_type(const std::string& type) {
  return type == "surface" || type == "surface_patch" || type == "graph";
}

/// Reference points of one cell: corners, edge midpoints and the rule's points (which lie inside
/// every polynomial piece of a macro-element).
QuadratureRule probe_points(CellShape shape, const QuadratureRule& inside) {
  QuadratureRule rule = inside;
  for (double t : {0.0, 0.5})
    for (int e = 0; e < num_edges(shape); ++e) rule.points.push_back(reference_edge_point(shape, e, t));
  rule.weights.assign(rule.points.size(), 0.0);
  return rule;
}

/// The height and its derivatives must be finite where the space will use them: quadrature alone
/// would miss a pole on a mesh line, and NaN geometry would surface later as a solver failure.
void check_height_finite(const GraphSurfaceSpace& space, const ConfigNode& height) {
  static const char* const kNames[] = {"g", "g_x", "g_y", "g_xx", "g_xy", "g_yy"};
  const Space& planar = space.planar();
  auto evaluator = planar.make_evaluator();
  PointValues geometry;
  Eigen::MatrixXd jets;
  for (int e = 0; e < planar.num_elements(); ++e) {
    const RulePtr inside = planar.quadrature(e, 1);
    const QuadratureRule rule = probe_points(planar.cell_shape(e), *inside);
    evaluator->evaluate_geometry(e, rule, geometry);
    space.height_jets(geometry.x, jets);
    for (Eigen::Index k = 0; k < jets.cols(); ++k)
      for (int d = 0; d < 6; ++d)
        if (!std::isfinite(jets(d, k)))
          height.fail(std::string(kNames[d]) + " is not finite at (x, y) = (" + format_number(geometry.x(0, k)) +
                      ", " + format_number(geometry.x(1, k)) + ") of element " + std::to_string(e) +
                      ": the graph surface needs a height that is smooth, with finite first and second "
                      "derivatives, on the whole planar domain");
  }
}

}  // namespace

bool is_graph_domain(const ConfigNode& domain) {
  if (!domain.is_map()) return false;
  const auto type = domain.find("type");
  return type && type->is_scalar() && type->as_string() == "graph";
}

const Space* planar_of_graph(const Space* space) {
  const auto* graph = dynamic_cast<const GraphSurfaceSpace*>(space);
  return graph ? &graph->planar() : nullptr;
}

SpacePtr make_graph_space(const ConfigNode& domain, const ConfigNode& space,
                          const std::function<SpacePtr(const ConfigNode& over)>& build_planar) {
  domain.check_keys({"type", "height", "over"});
  domain["type"].as_choice({"graph"});
  const ConfigNode height = domain["height"];
  const ConfigNode over = domain["over"];
  if (!over.is_map() || !over.has("type"))
    over.fail("expected a planar domain block with its type, e.g. {type: rectangle, min: [-1, -1], max: [1, 1]}");
  if (const std::string type = over["type"].as_string(); is_surface_type(type))
    over["type"].fail("a graph surface lifts a planar domain; '" + type + "' is " +
                      (type == "graph" ? "a graph surface already" : "a surface in 3D"));
  if (space.is_map() && space.has("type") && space["type"].as_string() == "surface")
    space["type"].fail("the surface space lives on triangle-mesh surfaces (domain.type: surface); a graph "
                       "surface lifts a planar space: bspline, ws4, tmesh, g1 or g1_4split");
  const std::string text = height.as_string();
  const SymbolicFunction g = SymbolicFunction::parse(text, height.where());
  // Functions whose derivatives jump make a crease anywhere (not only where a probe point falls);
  // SymbolicFunction::str() prints GiNaC's abs, csgn and step under these names.
  for (const char* kink : {"abs(", "sign(", "step("})
    if (g.str().find(kink) != std::string::npos)
      height.fail("the height of a graph surface must be smooth (twice differentiable): abs, sign and step make "
                  "creases, where the lifted space is not C1 (got '" + text + "')");
  SpacePtr planar = build_planar(over);
  if (planar->ambient_dimension() != 2) over.fail("a graph surface lifts a planar domain; this one is in 3D");
  std::shared_ptr<const GraphSurfaceSpace> lifted;
  try {  // the constructor differentiates g twice
    lifted = std::make_shared<const GraphSurfaceSpace>(std::move(planar), g, text);
  } catch (const InputError& e) {
    throw InputError(std::string(e.what()) +
                     " (the height of a graph surface must be twice differentiable in closed form)");
  }
  check_height_finite(*lifted, height);
  return lifted;
}

DomainFamily graph_domain_family() {
  return {"graph", "height: g(x, y), over: a planar domain block (the space built on it, lifted onto z = g(x, y))", "",
          {}};
}

}  // namespace iga
