#include "assembly/parallel.hpp"
#include "assembly/assembler.hpp"
#include "config/progress.hpp"

#include <memory>

namespace iga {


Assembler::Assembler(const Space& space)
    : space_(space),
      table_(collect_element_dofs(space)),
      pattern_(sparsity_pattern(table_, space.dimension())),
      colours_(colour_elements(table_, space.dimension())) {}

template <class Scratch, class Work>
void Assembler::for_each_element(unsigned flags, Work&& work) const {
  // One thread team for all colours (evaluators and scratch are built once per thread); the
  // implicit barrier after each `omp for` keeps colours apart. Small meshes stay serial: there
  // the barriers would cost more than the work, notably on a machine busy with other processes.
  #pragma omp parallel if (worth_threads(space_.num_elements()))
  {
    ElementValues ev(space_, flags);
    Scratch scratch;
    for (const std::vector<int>& group : colours_) {
      const int m = static_cast<int>(group.size());
#pragma omp for schedule(dynamic, 16)
      for (int k = 0; k < m; ++k) work(group[k], ev, scratch), progress_tick();
    }
  }
}

SparseMatrix Assembler::matrix(BilinearForm form, int quad_degree) const {
  SparseMatrix A = pattern_;
  for_each_element<Eigen::MatrixXd>(flags_for(form), [&](int e, ElementValues& ev, Eigen::MatrixXd& local) {
    if (space_.closed_form_element_matrix(e, form, local)) {
      thread_local std::vector<int> dofs;
      dofs.assign(table_.begin(e), table_.begin(e + 1));
      scatter_add(dofs, local, A);
      return;
    }
    ev.reinit(e, *space_.quadrature(e, quad_degree));
    element_matrix(form, ev, local);
    scatter_add(ev.dofs(), local, A);
  });
  return A;
}

SplitMatrix Assembler::matrix_extended(BilinearForm form, int quad_degree) const {
  std::vector<long double> values(pattern_.nonZeros(), 0.0L);
  struct Scratch {
    MatrixXld local;
    std::vector<int> dofs;
  };
  for_each_element<Scratch>(flags_for(form), [&](int e, ElementValues& ev, Scratch& s) {
    if (space_.closed_form_element_matrix_extended(e, form, s.local)) {
      s.dofs.assign(table_.begin(e), table_.begin(e + 1));
      scatter_add(s.dofs, s.local, pattern_, values);
      return;
    }
    ev.reinit(e, *space_.quadrature(e, quad_degree));
    element_matrix_extended(form, ev, s.local);
    scatter_add(ev.dofs(), s.local, pattern_, values);
  });
  return split_matrix(pattern_, values);
}

Eigen::VectorXd Assembler::load(const ScalarField& f, int quad_degree) const {
  // Geometry first, then the transposed evaluation Σ_q f(x_q) JxW_q N_i(x_q) (Space::Evaluator::
  // integrate_values), so a space never has to tabulate all its functions for a load vector.
  Eigen::VectorXd b = Eigen::VectorXd::Zero(space_.dimension());
  #pragma omp parallel if (worth_threads(space_.num_elements()))
  {
    const std::unique_ptr<Space::Evaluator> evaluator = space_.make_evaluator();
    PointValues geometry;
    Eigen::VectorXd jxw, fw, local;
    for (const std::vector<int>& group : colours_) {
      const int m = static_cast<int>(group.size());
#pragma omp for schedule(dynamic, 16)
      for (int k = 0; k < m; ++k) {
        const int e = group[k];
        progress_tick();
        const RulePtr rule_ptr = space_.quadrature(e, quad_degree);  // keeps the rule alive
        const QuadratureRule& rule = *rule_ptr;
        evaluator->evaluate_geometry(e, rule, geometry);
        integration_weights(rule, geometry, jxw);
        fw.resize(rule.size());
        for (int q = 0; q < rule.size(); ++q) fw(q) = f(geometry.x.col(q)) * jxw(q);
        evaluator->integrate_values(e, rule, geometry, fw, local);
        for (int i = 0; i < local.size(); ++i) b(geometry.dofs[i]) += local(i);
      }
    }
  }
  return b;
}

Eigen::VectorXd Assembler::boundary_load(const std::vector<BoundaryEdge>& edges, const BoundaryField& g,
                                         BoundaryTest test, int quad_degree) const {
  // Boundary work is O(sqrt(elements)); it runs serially.
  Eigen::VectorXd b = Eigen::VectorXd::Zero(space_.dimension());
  const unsigned flags = test == BoundaryTest::value ? update_values : update_gradients;
  ElementValues ev(space_, flags);
  for (const BoundaryEdge& be : edges) {
    ev.reinit_edge(be.element, be.local_edge, *space_.edge_quadrature(be.element, be.local_edge, quad_degree));
    const PointValues& v = ev.values();
    for (int k = 0; k < ev.num_points(); ++k) {
      const Point2 n = ev.normal().col(k);
      const double gw = g(v.x.col(k), n) * ev.jxw()(k);
      for (int i = 0; i < ev.num_functions(); ++i) {
        const double test_value =
            test == BoundaryTest::value ? v.value(i, k) : v.dx(i, k) * n.x() + v.dy(i, k) * n.y();
        b(ev.dofs()[i]) += gw * test_value;
      }
    }
  }
  return b;
}

}  // namespace iga
