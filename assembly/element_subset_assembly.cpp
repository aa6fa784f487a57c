#include "assembly/element_subset_assembly.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

#include "assembly/integrators.hpp"
#include "assembly/parallel.hpp"
#include "assembly/split_matrix.hpp"
#include "spaces/closed_forms.hpp"
#include "spaces/element_values.hpp"

namespace iga {

namespace {
/// Elements computed in parallel before being handed on serially: large enough to keep threads
/// busy, small enough that the stored element matrices stay a few megabytes.
constexpr int batch_size = 512;

struct ElementSystem {
  std::vector<int> dofs;
  Eigen::MatrixXd matrix;
  Eigen::VectorXd load;
  MatrixXld extended;
};

/// The element loop of both variants: `Extended` keeps the long double matrix.
template <bool Extended, class Sink>
void element_systems(const Space& space, const std::vector<int>& elements, BilinearForm form, const ScalarField& f,
                     int quad_degree, const Sink& sink) {
  const int n = static_cast<int>(elements.size());
  std::vector<ElementSystem> batch(std::min(n, batch_size));
#pragma omp parallel if (worth_threads(n))
  {
    // As in Assembler: a space's closed-form element matrix when it has one (no tabulation of the
    // basis), and the load by the transposed evaluation Σ_q f(x_q) JxW_q N_i(x_q).
    ElementValues ev(space, flags_for(form));
    const std::unique_ptr<Space::Evaluator> evaluator = space.make_evaluator();
    PointValues geometry;
    Eigen::VectorXd jxw, fw;
    for (int first = 0; first < n; first += batch_size) {
      const int m = std::min(batch_size, n - first);
#pragma omp for schedule(dynamic, 8)
      for (int k = 0; k < m; ++k) {
        const int e = elements[first + k];
        ElementSystem& s = batch[k];
        const RulePtr rule = space.quadrature(e, quad_degree);  // keeps the rule alive
        evaluator->evaluate_geometry(e, *rule, geometry);
        integration_weights(*rule, geometry, jxw);
        fw.resize(rule->size());
        for (int q = 0; q < rule->size(); ++q) fw(q) = f(geometry.x.col(q)) * jxw(q);
        evaluator->integrate_values(e, *rule, geometry, fw, s.load);
        s.dofs = geometry.dofs;
        // The extended closed form, rounded once: the one Assembler::matrix_extended uses (the
        // double one of some spaces runs Eigen's threaded products per element, slow here).
        if (space.closed_forms() && space.closed_forms()->element_matrix(e, form, s.extended)) {
          if constexpr (!Extended) s.matrix = s.extended.cast<double>();
        } else {
          ev.reinit(e, *rule);
          if constexpr (Extended)
            element_matrix_extended(form, ev, s.extended);
          else
            element_matrix(form, ev, s.matrix);
        }
      }
#pragma omp single
      for (int k = 0; k < m; ++k) {
        if constexpr (Extended)
          sink(elements[first + k], batch[k].dofs, batch[k].extended, batch[k].load);
        else
          sink(elements[first + k], batch[k].dofs, batch[k].matrix, batch[k].load);
      }
      // implicit barrier: the batch is reused only after the sink has seen it
    }
  }
}

}  // namespace

void for_each_element_system(const Space& space, const std::vector<int>& elements, BilinearForm form,
                             const ScalarField& f, int quad_degree, const ElementSystemSink& sink) {
  element_systems<false>(space, elements, form, f, quad_degree, sink);
}

void for_each_element_system_extended(const Space& space, const std::vector<int>& elements, BilinearForm form,
                                      const ScalarField& f, int quad_degree, const ElementSystemSinkExtended& sink) {
  element_systems<true>(space, elements, form, f, quad_degree, sink);
}

Eigen::VectorXd edge_load(const Space& space, const std::vector<BoundaryEdge>& edges, const BoundaryField& g,
                          bool normal_derivative, int quad_degree) {
  Eigen::VectorXd b = Eigen::VectorXd::Zero(space.dimension());
  ElementValues ev(space, normal_derivative ? update_gradients : update_values);
  for (const BoundaryEdge& be : edges) {
    ev.reinit_edge(be.element, be.local_edge, *space.edge_quadrature(be.element, be.local_edge, quad_degree));
    const PointValues& v = ev.values();
    for (int k = 0; k < ev.num_points(); ++k) {
      const Point2 n = ev.normal().col(k);
      const double gw = g(v.x.col(k), n) * ev.jxw()(k);
      for (int i = 0; i < ev.num_functions(); ++i)
        b(ev.dofs()[i]) += gw * (normal_derivative ? v.dx(i, k) * n.x() + v.dy(i, k) * n.y() : v.value(i, k));
    }
  }
  return b;
}

std::vector<Point2> element_centres(const Space& space) {
  const int ne = space.num_elements();
  std::vector<Point2> centres(ne);
  const std::unique_ptr<Space::Evaluator> evaluator = space.make_evaluator();
  PointValues geometry;
  Eigen::VectorXd jxw;
  for (int e = 0; e < ne; ++e) {
    const RulePtr rule = space.quadrature(e, 1);
    evaluator->evaluate_geometry(e, *rule, geometry);
    integration_weights(*rule, geometry, jxw);
    centres[e] = geometry.x * jxw / jxw.sum();
  }
  return centres;
}

SquaredErrors squared_errors_on_elements(const Space& space, const std::vector<int>& elements,
                                         const Eigen::VectorXd& coefficients, const ExactSolution& exact,
                                         int quad_degree) {
  const bool grad = exact.has_gradient(), hess = exact.has_hessian();
  const unsigned flags = update_values | (grad ? update_gradients : 0u) | (hess ? update_hessians : 0u);
  const int n = static_cast<int>(elements.size());
  double l2 = 0, h1 = 0, h2 = 0;
#pragma omp parallel reduction(+ : l2, h1, h2) if (worth_threads(n))
  {
    const std::unique_ptr<Space::Evaluator> evaluator = space.make_evaluator();
    PointValues geometry;
    FunctionValues uh;
    Eigen::VectorXd jxw;
#pragma omp for schedule(dynamic, 16)
    for (int k = 0; k < n; ++k) {
      const int e = elements[k];
      const RulePtr rule = space.quadrature(e, quad_degree);
      evaluator->evaluate_function(e, *rule, coefficients, flags, geometry, uh);
      integration_weights(*rule, geometry, jxw);
      for (int q = 0; q < rule->size(); ++q) {
        const Point2 x = geometry.x.col(q);
        const double w = jxw(q);
        l2 += w * std::pow(uh.value(q) - exact.u(x), 2);
        if (grad) h1 += w * (std::pow(uh.dx(q) - exact.ux(x), 2) + std::pow(uh.dy(q) - exact.uy(x), 2));
        if (hess)
          h2 += w * (std::pow(uh.dxx(q) - exact.uxx(x), 2) + 2 * std::pow(uh.dxy(q) - exact.uxy(x), 2) +
                     std::pow(uh.dyy(q) - exact.uyy(x), 2));
      }
    }
  }
  return {l2, h1, h2};
}

ErrorNorms error_norms_from_squares(const SquaredErrors& total, const ExactSolution& exact) {
  ErrorNorms r;
  r.l2 = std::sqrt(total.l2);
  if (exact.has_gradient()) r.h1 = std::sqrt(total.h1);
  if (exact.has_hessian()) r.h2 = std::sqrt(total.h2);
  return r;
}

}  // namespace iga
