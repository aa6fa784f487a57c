#include "solver/study_functionals.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include "spaces/surface_point_location.hpp"

namespace iga {

namespace {

/// Points of a surface given in a config: found to 1e-7 of their size (the configs write 16 digits).
double surface_point_tolerance(const Eigen::Vector3d& x) { return 1e-7 * (1.0 + x.norm()); }

std::shared_ptr<QuadratureRule> one_point(const Point2& r) {
  auto rule = std::make_shared<QuadratureRule>();
  rule->points = {r};
  rule->weights = {0.0};
  return rule;
}

}  // namespace

std::vector<FunctionalSpec> parse_functionals(const ConfigNode& node, const Space& coarse, int components) {
  std::vector<FunctionalSpec> out;
  const bool surface = coarse.ambient_dimension() == 3;
  std::optional<PointLocator> locator;
  std::unique_ptr<Space::Evaluator> evaluator;
  for (const std::string& name : node.keys()) {
    const ConfigNode f = node[name];
    FunctionalSpec spec;
    spec.name = name;
    if (name.empty() || name.find_first_of(",\" \t") != std::string::npos)
      f.fail("a functional's name becomes a CSV column: no commas, quotes or spaces");
    if (surface) {
      // The entries are named by the user, so their keys are checked here rather than declared.
      const std::string form = components == 3 ? "{point: [x, y, z], component: x|y|z}" : "{point: [x, y, z]}";
      if (!f.is_map() || !f.has("point") || f.keys().size() != (components == 3 ? 2u : 1u) ||
          (components == 3 && !f.has("component")))
        f.fail("a functional on a surface is " + form);
      spec.kind = FunctionalSpec::Kind::surface_point;
      const std::vector<double> p = f["point"].as_doubles();
      if (p.size() != 3) f["point"].fail("a point of a surface is [x, y, z]");
      spec.point3 = Eigen::Vector3d(p[0], p[1], p[2]);
      if (components == 3) {
        const ConfigNode cn = f["component"];
        const std::string c = cn.is_scalar() ? cn.as_string() : "";
        if (c != "x" && c != "y" && c != "z") cn.fail("a displacement component is x, y or z");
        spec.component = c == "x" ? 0 : c == "y" ? 1 : 2;
      }
      if (!evaluator) evaluator = coarse.make_evaluator();
      if (!locate_on_surface(coarse, spec.point3, *evaluator, surface_point_tolerance(spec.point3)))
        f["point"].fail("the point is not on the surface (to 1e-7 relative)");
      out.push_back(spec);
      continue;
    }
    if (!f.is_map() || f.keys().size() != 1 || (!f.has("point") && !f.has("integral")))
      f.fail("a functional is {point: [x, y]} or {integral: u}");
    if (f.has("point")) {
      spec.kind = FunctionalSpec::Kind::point;
      spec.point = f["point"].as_point();
      if (!locator) locator.emplace(coarse.shared_from_this());
      if (!locator->locate(spec.point)) f["point"].fail("the point is not in the domain");
    } else {
      if (f["integral"].as_string() != "u") f["integral"].fail("the integral functional is integral: u");
    }
    out.push_back(spec);
  }
  return out;
}

std::vector<double> evaluate_functionals(const std::vector<FunctionalSpec>& functionals, const Space& space,
                                         const Eigen::VectorXd& coefficients, const PointLocator* locator,
                                         const WorkShare& share) {
  std::vector<double> values;
  std::optional<PointLocator> own;
  if (!locator && std::any_of(functionals.begin(), functionals.end(),
                              [](const FunctionalSpec& f) { return f.kind == FunctionalSpec::Kind::point; }))
    locator = &own.emplace(space.shared_from_this());
  const std::unique_ptr<Space::Evaluator> evaluator = space.make_evaluator();
  PointValues geometry;
  FunctionValues uh;
  const int n = space.dimension();
  for (const FunctionalSpec& f : functionals) {
    if (f.kind == FunctionalSpec::Kind::surface_point || f.kind == FunctionalSpec::Kind::point) {
      const bool on_surface = f.kind == FunctionalSpec::Kind::surface_point;
      const auto at = on_surface ? locate_on_surface(space, f.point3, *evaluator, surface_point_tolerance(f.point3))
                                 : locator->locate(f.point, *evaluator);
      double value = std::numeric_limits<double>::quiet_NaN();
      if (at) {
        const auto rule = one_point(at->reference);
        // A shell's displacement: the component's block (copied only then).
        const bool vector = coefficients.size() > n;
        const Eigen::VectorXd block = vector ? Eigen::VectorXd(coefficients.segment(f.component * n, n)) : Eigen::VectorXd();
        evaluator->evaluate_function(at->element, *rule, vector ? block : coefficients, update_values, geometry, uh);
        value = uh.value(0);
      }
      value = share.first(value);
      if (std::isnan(value))
        throw std::runtime_error("functional '" + f.name + "': point not found on this level's " +
                                 (on_surface ? "surface" : "mesh"));
      values.push_back(value);
    } else {
      double sum = 0;
      Eigen::VectorXd jxw;
      const int count = share.elements ? static_cast<int>(share.elements->size()) : space.num_elements();
      for (int i = 0; i < count; ++i) {
        const int e = share.elements ? (*share.elements)[i] : i;
        const RulePtr rule = space.quadrature(e, 2 * space.degree() + 2);
        evaluator->evaluate_function(e, *rule, coefficients, update_values, geometry, uh);
        integration_weights(*rule, geometry, jxw);
        sum += jxw.dot(uh.value);
      }
      values.push_back(share.sum(sum));
    }
  }
  return values;
}

std::optional<double> richardson_order(const std::vector<double>& values, const std::vector<double>& h, std::size_t l) {
  if (l < 2 || l >= values.size() || l >= h.size()) return std::nullopt;
  const double d_prev = std::abs(values[l - 1] - values[l - 2]), d = std::abs(values[l] - values[l - 1]);
  if (!(d_prev > 0) || !(d > 0) || !(h[l - 1] > 0) || !(h[l] > 0) || h[l - 1] == h[l]) return std::nullopt;
  return std::log(d_prev / d) / std::log(h[l - 1] / h[l]);
}

}  // namespace iga
