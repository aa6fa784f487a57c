#include "assembly/surface_load.hpp"

#include <omp.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "assembly/parallel.hpp"
#include "spaces/element_values.hpp"

namespace iga {

namespace {

/// Σ_e of each element's local vector (`local_vector(e, ev, local)` after ev.reinit; copied per thread), scattered by its
/// dofs. Each thread sums a fixed range of elements (static schedule) into its own vector, and the
/// vectors are added in thread order afterwards: the result does not depend on timing, and the
/// extra work is O(dofs) per thread against O(elements · points) for the integrals.
template <class LocalVector>
Eigen::VectorXd sum_element_vectors(const Space& space, unsigned flags, int quad_degree,
                                    const std::vector<int>* elements, const char* who, LocalVector local_vector) {
  if (space.ambient_dimension() != 3) throw std::logic_error(std::string(who) + ": the space is not on a surface in 3D");
  const int ne = elements ? static_cast<int>(elements->size()) : space.num_elements();
  std::vector<Eigen::VectorXd> partial;
#pragma omp parallel if (worth_threads(ne))
  {
#pragma omp single
    partial.assign(omp_get_num_threads(), Eigen::VectorXd::Zero(space.dimension()));
    Eigen::VectorXd& mine = partial[omp_get_thread_num()];
    ElementValues ev(space, flags);
    LocalVector kernel = local_vector;  // one copy per thread: it owns its scratch vectors
    Eigen::VectorXd local;
#pragma omp for schedule(static)
    for (int k = 0; k < ne; ++k) {
      const int e = elements ? (*elements)[k] : k;
      const RulePtr rule = space.quadrature(e, quad_degree);
      ev.reinit(e, *rule);
      kernel(e, ev, local);
      const std::vector<int>& dofs = ev.values().dofs;
      for (int i = 0; i < local.size(); ++i) mine(dofs[i]) += local(i);
    }
  }
  Eigen::VectorXd b = Eigen::VectorXd::Zero(space.dimension());
  for (const Eigen::VectorXd& p : partial) b += p;
  return b;
}

}  // namespace

Eigen::VectorXd surface_load(const Space& space, const SurfaceSource& f, int quad_degree,
                             const std::vector<int>* elements) {
  return sum_element_vectors(space, update_values | update_surface_curvature, quad_degree, elements, "surface_load",
                             [&f, fw = Eigen::VectorXd()](int, const ElementValues& ev, Eigen::VectorXd& local) mutable {
                               const PointValues& v = ev.values();
                               fw.resize(ev.num_points());
                               for (int k = 0; k < ev.num_points(); ++k)
                                 fw(k) = f(v.x3.col(k), v.normal3.col(k), v.mean_curvature(k)) * ev.jxw()(k);
                               local.noalias() = v.value * fw;
                             });
}

Eigen::VectorXd surface_element_load(const Space& space, const ElementSurfaceSource& f, int quad_degree,
                                     const std::vector<int>* elements) {
  return sum_element_vectors(space, update_values | update_surface_curvature, quad_degree, elements,
                             "surface_element_load",
                             [&f, fw = Eigen::VectorXd()](int e, const ElementValues& ev, Eigen::VectorXd& local) mutable {
                               const PointValues& v = ev.values();
                               fw.resize(ev.num_points());
                               for (int k = 0; k < ev.num_points(); ++k)
                                 fw(k) = f(e, v.x3.col(k), v.normal3.col(k)) * ev.jxw()(k);
                               local.noalias() = v.value * fw;
                             });
}

Eigen::VectorXd surface_form_load(const Space& space, const SurfaceSource& f0, const SurfaceSource& f2,
                                  int quad_degree, const std::vector<int>* elements) {
  return sum_element_vectors(
      space, update_values | update_hessians | update_surface_curvature, quad_degree, elements, "surface_form_load",
      [&f0, &f2, w0 = Eigen::VectorXd(), w2 = Eigen::VectorXd()](int, const ElementValues& ev,
                                                                Eigen::VectorXd& local) mutable {
        const PointValues& v = ev.values();
        const int q = ev.num_points();
        w0.resize(q);
        w2.resize(q);
        for (int j = 0; j < q; ++j) {
          const Eigen::Vector3d x = v.x3.col(j), n = v.normal3.col(j);
          const double H = v.mean_curvature(j);
          w0(j) = f0(x, n, H) * ev.jxw()(j);
          w2(j) = f2(x, n, H) * ev.jxw()(j);
        }
        // Δ_Γ N_i: the trace of the covariant Hessian.
        local.noalias() = v.value * w0 + (v.dxx + v.dyy + v.dzz) * w2;
      });
}

}  // namespace iga
