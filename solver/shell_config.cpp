#include "solver/shell_config.hpp"

#include <algorithm>
#include <cmath>

namespace iga {

namespace {

/// A list of three expressions in x, y, z (numbers allowed).
std::vector<SymbolicFunction> parse_vector(const ConfigNode& node, const std::string& what) {
  if (!node.is_sequence() || node.items().size() != 3)
    node.fail(what + " is a list of three expressions in x, y, z (its x, y and z components), e.g. [0, 0, -90]");
  std::vector<SymbolicFunction> out;
  for (const ConfigNode& item : node.items()) {
    if (!item.is_scalar()) item.fail(what + ": each component is a number or an expression in x, y, z");
    out.push_back(SymbolicFunction::parse_xyz(item.as_string(), item.where()));
  }
  return out;
}

/// Three finite numbers [a, b, c].
Eigen::Vector3d triple(const ConfigNode& node, const std::string& what) {
  const std::vector<double> v = node.is_sequence() ? node.as_doubles() : std::vector<double>{};
  if (v.size() != 3 || !std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2]))
    node.fail(what + " is a list of three finite numbers [x, y, z]");
  return {v[0], v[1], v[2]};
}

/// point_loads: [{point: [x, y, z], force: [fx, fy, fz]}, ...]
std::vector<ShellPointLoad> parse_point_loads(const ConfigNode& node) {
  if (!node.is_sequence() || node.items().empty())
    node.fail("point_loads is a list of {point: [x, y, z], force: [fx, fy, fz]}");
  std::vector<ShellPointLoad> out;
  for (const ConfigNode& item : node.items()) {
    // Entries of a list are not declared keys: checked here.
    if (!item.is_map() || !item.has("point") || !item.has("force") ||
        item.keys().size() != (item.has("snap") ? 3u : 2u))
      item.fail("a point load is {point: [x, y, z], force: [fx, fy, fz]} (a point of the surface and the force there), "
                "with snap: true to apply it at the surface's nearest point");
    ShellPointLoad p;
    p.point = triple(item["point"], "a point load's point");
    p.force = triple(item["force"], "a point load's force");
    if (const auto snap = item.find("snap")) p.snap = snap->as_bool();
    p.where = item["point"].where();
    out.push_back(p);
  }
  return out;
}

double positive(const ConfigNode& node, const std::string& what) {
  const double v = node.as_double();
  if (!(v > 0.0 && std::isfinite(v))) node.fail(what + " must be a number > 0");
  return v;
}

}  // namespace

ProblemSpec parse_shell_problem(const ConfigNode& node) {
  node.check_keys({"pde", "material", "load", "pressure", "point_loads", "exact", "boundary"});
  ProblemSpec p;
  p.pde = Pde::kirchhoff_love_shell;
  ShellSpec shell;

  const ConfigNode material = node["material"];
  material.check_keys({"youngs_modulus", "poisson_ratio", "thickness"});
  shell.material.youngs_modulus = positive(material["youngs_modulus"], "youngs_modulus");
  shell.material.thickness = positive(material["thickness"], "thickness");
  if (const auto nu = material.find("poisson_ratio")) {
    shell.material.poisson_ratio = nu->as_double();
    // ν in [0, 1/2): the energy's ν (tr ε)² term is then a nonnegative square (shell_integrators.hpp).
    if (!(shell.material.poisson_ratio >= 0.0 && shell.material.poisson_ratio < 0.5))
      nu->fail("poisson_ratio must be in [0, 0.5)");
  }

  const auto load = node.find("load");
  const auto pressure = node.find("pressure");
  const auto points = node.find("point_loads");
  if (!load && !pressure && !points)
    node.fail("give 'load' (the force per unit area as [fx, fy, fz], expressions in x, y, z), 'pressure' (a force "
              "per unit area along the outward normal, an expression in x, y, z) or 'point_loads' "
              "([{point: [x, y, z], force: [fx, fy, fz]}, ...]), or several");
  if (load) {
    shell.load = parse_vector(*load, "load");
    p.source_where = load->where();
  } else {
    shell.load.assign(3, SymbolicFunction::constant(0.0));
  }
  if (pressure) {
    if (!pressure->is_scalar())
      pressure->fail("pressure is one number or expression in x, y, z: the force per unit area along the surface's "
                     "outward normal (negative pushes inwards)");
    shell.pressure = SymbolicFunction::parse_xyz(pressure->as_string(), pressure->where());
    shell.pressure_where = pressure->where();
    if (!load) p.source_where = pressure->where();
  }
  if (points) {
    shell.point_loads = parse_point_loads(*points);
    if (!load && !pressure) p.source_where = points->where();
  }
  shell.loads_where = p.source_where;
  if (const auto exact = node.find("exact")) {
    shell.exact = parse_vector(*exact, "exact");
    p.data_where = exact->where();
  }

  // No boundary: a free shell (its rigid motions are removed, shell_rigid_motions.hpp).
  const auto boundary = node.find("boundary");
  if (boundary && (!boundary->is_map() || boundary->keys().empty()))
    boundary->fail("expected a map from boundary part (all, left, ...) to {fixed: [components]}; leave 'boundary' out "
                   "for a free shell");
  for (const std::string& name : boundary ? boundary->keys() : std::vector<std::string>{}) {
    const ConfigNode entry = (*boundary)[name];
    // The parts are named by the user, so their keys are checked here rather than declared.
    const std::vector<std::string> keys = entry.is_map() ? entry.keys() : std::vector<std::string>{};
    if (!entry.is_map() || keys.empty() ||
        std::any_of(keys.begin(), keys.end(), [](const std::string& k) { return k != "fixed" && k != "rotation"; }))
      entry.fail("a shell's support is {fixed: [x, y, z]} (the displacement components held) and/or "
                 "{rotation: held} (the rotation about the edge held: clamped with all three fixed, or a symmetry plane)");
    ShellSupport support{name, {false, false, false}, false, entry.where()};
    if (const auto fixed = entry.find("fixed")) {
      if (!fixed->is_sequence() || fixed->items().empty())
        fixed->fail("fixed is a list of displacement components: any of x, y, z, e.g. [y, z]");
      for (const ConfigNode& c : fixed->items()) {
        const std::string k = c.is_scalar() ? c.as_string() : "";
        if (k != "x" && k != "y" && k != "z") c.fail("a displacement component is x, y or z");
        const int i = k == "x" ? 0 : k == "y" ? 1 : 2;
        if (support.fixed[i]) c.fail("component '" + k + "' is listed twice");
        support.fixed[i] = true;
      }
    }
    if (const auto rotation = entry.find("rotation")) {
      const std::string r = rotation->is_scalar() ? rotation->as_string() : "";
      if (r != "held" && r != "free") rotation->fail("rotation is 'held' (clamped, symmetry plane) or 'free' (the default)");
      support.rotation_held = r == "held";
    }
    shell.supports.push_back(support);
  }
  p.shell = std::move(shell);
  p.terms = {shell_integrator(ShellEnergy::membrane, p.shell->material),
             shell_integrator(ShellEnergy::bending, p.shell->material)};
  return p;
}

}  // namespace iga
