#include "assembly/surface_load.hpp"

#include <stdexcept>

#include "spaces/element_values.hpp"

namespace iga {

Eigen::VectorXd surface_load(const Space& space, const SurfaceSource& f, int quad_degree) {
  if (space.ambient_dimension() != 3) throw std::logic_error("surface_load: the space is not on a surface in 3D");
  Eigen::VectorXd b = Eigen::VectorXd::Zero(space.dimension());
  ElementValues ev(space, update_values | update_surface_curvature);
  Eigen::VectorXd fw, local;
  for (int e = 0; e < space.num_elements(); ++e) {
    const RulePtr rule = space.quadrature(e, quad_degree);
    ev.reinit(e, *rule);
    const PointValues& v = ev.values();
    fw.resize(ev.num_points());
    for (int k = 0; k < ev.num_points(); ++k)
      fw(k) = f(v.x3.col(k), v.normal3.col(k), v.mean_curvature(k)) * ev.jxw()(k);
    local.noalias() = v.value * fw;
    for (int i = 0; i < local.size(); ++i) b(v.dofs[i]) += local(i);
  }
  return b;
}

}  // namespace iga
