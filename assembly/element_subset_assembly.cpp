#include "assembly/element_subset_assembly.hpp"

#include <algorithm>
#include <memory>
#ifdef _OPENMP
#include <omp.h>
#endif

#include "assembly/assembler.hpp"
#include "assembly/integrators.hpp"
#include "assembly/parallel.hpp"
#include "config/progress.hpp"
#include "spaces/element_values.hpp"

namespace iga {

namespace {
/// Elements computed before being handed on serially. With a thread team, 512: each batch ends in
/// barriers at which the threads idle while one hands the batch on, and smaller batches made those
/// waits cost (128 for two threads: the 10⁶ cubic B-spline assembly 6.0 → 6.9 s). With one thread
/// (every rank of an MPI run on a full node) there is no team to wait for, and the stored element
/// matrices are memory every rank holds whatever the rank count: 512 quintic G1 matrices in
/// double-double are 10.6 MB, the 4-split's macro-elements far more, so 64.
int batch_size(int elements) {
  int threads = 1;
#ifdef _OPENMP
  if (worth_threads(elements)) threads = omp_get_max_threads();
#endif
  return threads > 1 ? 512 : 64;
}
}  // namespace

void for_each_element_matrix(const Space& space, const std::vector<int>& elements, const std::vector<FormTerm>& terms,
                             int quad_degree, const ElementMatrixSink& sink, int components) {
  unsigned flags = 0;
  for (const FormTerm& t : terms) {
    prepare_extended_element_matrices(space, *t);
    flags |= t->flags();
  }
  const int n = static_cast<int>(elements.size());
  const int batch = batch_size(n);
  std::vector<DoubleDoubleMatrix> slots(std::min(n, batch));
  std::vector<const DoubleDoubleMatrix*> matrix(slots.size());
  std::vector<std::vector<int>> dofs(slots.size());
#pragma omp parallel if (worth_threads(n))
  {
    ElementValues ev(space, flags);
    DoubleDoubleMatrix term;
    std::vector<int> term_dofs;
    for (int first = 0; first < n; first += batch) {
      const int m = std::min(batch, n - first);
#pragma omp for schedule(dynamic, 8)
      for (int k = 0; k < m; ++k) {
        const int e = elements[first + k];
        matrix[k] = &extended_element_matrix(space, e, *terms[0], quad_degree, ev, slots[k], dofs[k], components);
        if (terms.size() == 1) continue;
        // Σ terms in double-double (coefficients applied by each term); every term's rows come in
        // the element's one order.
        DoubleDoubleMatrix& sum = slots[k];
        if (matrix[k] != &sum) sum = *matrix[k];
        for (std::size_t t = 1; t < terms.size(); ++t) {
          const DoubleDoubleMatrix& a = extended_element_matrix(space, e, *terms[t], quad_degree, ev, term, term_dofs,
                                                                  components);
          for (Eigen::Index j = 0; j < sum.cols(); ++j)
            for (Eigen::Index i = 0; i < sum.rows(); ++i) sum.set(i, j, sum(i, j) + a(i, j));
        }
        matrix[k] = &sum;
      }
#pragma omp single
      for (int k = 0; k < m; ++k) sink(elements[first + k], dofs[k], *matrix[k]);
      // implicit barrier: the batch is reused only after the sink has seen it
    }
  }
}

Eigen::VectorXd subset_load(const Space& space, const std::vector<int>& elements, const BatchField& f,
                            int quad_degree) {
  // Geometry first, then the transposed evaluation Σ_q f(x_q) JxW_q N_i(x_q) (Space::Evaluator::
  // integrate_values), so a space never has to tabulate all its functions for a load vector.
  // Element vectors go to their own slots and are added in the order given afterwards: the same
  // sums whatever the number of threads.
  keep_eigen_serial();
  const int n = static_cast<int>(elements.size());
  std::vector<Eigen::VectorXd> locals(n);
  std::vector<std::vector<int>> dofs(n);
#pragma omp parallel if (worth_threads(n))
  {
    const std::unique_ptr<Space::Evaluator> evaluator = space.make_evaluator();
    PointValues geometry;
    Eigen::VectorXd jxw, fw;
    Eigen::MatrixXd fx;
#pragma omp for schedule(dynamic, 16)
    for (int k = 0; k < n; ++k) {
      progress_tick();
      const RulePtr rule = space.quadrature(elements[k], quad_degree);  // keeps the rule alive
      evaluator->evaluate_geometry(elements[k], *rule, geometry);
      integration_weights(*rule, geometry, jxw);
      f(geometry.x, fx);
      fw = fx.row(0).transpose().cwiseProduct(jxw);
      evaluator->integrate_values(elements[k], *rule, geometry, fw, locals[k]);
      dofs[k] = geometry.dofs;
    }
  }
  Eigen::VectorXd b = Eigen::VectorXd::Zero(space.dimension());
  for (int k = 0; k < n; ++k)
    for (int i = 0; i < locals[k].size(); ++i) b(dofs[k][i]) += locals[k](i);
  return b;
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

std::vector<Point2> element_centres(const Space& space) { return element_centres(space, 0, space.num_elements()); }

std::vector<Point2> element_centres(const Space& space, int first, int last) {
  std::vector<Point2> centres(std::max(0, last - first));
  const std::unique_ptr<Space::Evaluator> evaluator = space.make_evaluator();
  PointValues geometry;
  Eigen::VectorXd jxw;
  for (int e = first; e < last; ++e) {
    const RulePtr rule = space.quadrature(e, 1);
    evaluator->evaluate_geometry(e, *rule, geometry);
    integration_weights(*rule, geometry, jxw);
    centres[e - first] = geometry.x * jxw / jxw.sum();
  }
  return centres;
}

}  // namespace iga
