#include "assembly/parallel.hpp"
#include "assembly/assembler.hpp"
#include "assembly/element_subset_assembly.hpp"
#include "config/progress.hpp"
#include "spaces/closed_forms.hpp"

#include <omp.h>

#include <algorithm>
#include <cassert>
#include <memory>
#include <numeric>
#include <optional>

namespace iga {

void expand_component_dofs(std::vector<int>& dofs, int components, int dimension) {
  if (components == 1) return;
  const std::size_t n = dofs.size();
  dofs.resize(n * components);
  for (int c = 1; c < components; ++c)
    for (std::size_t i = 0; i < n; ++i) dofs[c * n + i] = c * dimension + dofs[i];
}

ElementDofTable component_dofs(const ElementDofTable& scalar, int components, int dimension) {
  if (components == 1) return scalar;
  ElementDofTable t;
  t.offsets.resize(scalar.offsets.size());
  for (std::size_t e = 0; e < scalar.offsets.size(); ++e) t.offsets[e] = components * scalar.offsets[e];
  t.dofs.reserve(scalar.dofs.size() * components);
  for (int e = 0; e < scalar.num_elements(); ++e)
    for (int c = 0; c < components; ++c)
      for (const int* d = scalar.begin(e); d != scalar.begin(e + 1); ++d) t.dofs.push_back(c * dimension + *d);
  return t;
}

Assembler::Assembler(const Space& space, int components)
    : space_(space),
      table_(component_dofs(collect_element_dofs(space), components, space.dimension())),
      pattern_(sparsity_pattern(table_, components * space.dimension())),
      components_(components) {
  for (int e = 0; e < table_.num_elements(); ++e) max_local_ = std::max(max_local_, table_.size(e));
}

namespace {

/// Double-double entries accumulated straight into the two arrays of a SplitMatrix: no array of
/// pairs to allocate (16 bytes per nonzero) and split afterwards.
struct SplitValues {
  double* hi;
  double* lo;
};
inline void add_entry(double* values, std::ptrdiff_t p, double v) { values[p] += v; }
inline void add_entry(SplitValues values, std::ptrdiff_t p, const DoubleDouble& v) {
  const DoubleDouble sum = DoubleDouble(values.hi[p], values.lo[p]) + v;
  values.hi[p] = sum.hi;
  values.lo[p] = sum.lo;
}

/// Add the columns j of `local` with dofs[j] in [first, last) into `values` (aligned with the
/// value array of `pattern`): the part of the element matrix this thread owns. The element's rows
/// are visited in increasing dof order, so each pattern column is walked once from its start
/// instead of searched once per row.
template <class Local, class Values>
void scatter_owned_columns(const std::vector<int>& dofs, const Local& local, const SparseMatrix& pattern,
                           Values values, int first, int last) {
  const int n = static_cast<int>(dofs.size());
  const int* outer = pattern.outerIndexPtr();
  const int* inner = pattern.innerIndexPtr();
  thread_local std::vector<int> order;
  order.resize(n);
  bool sorted_yet = false;
  for (int j = 0; j < n; ++j) {
    if (dofs[j] < first || dofs[j] >= last) continue;
    if (!sorted_yet) {
      std::iota(order.begin(), order.end(), 0);
      std::sort(order.begin(), order.end(), [&](int a, int b) { return dofs[a] < dofs[b]; });
      sorted_yet = true;
    }
    const int* pos = inner + outer[dofs[j]];
    [[maybe_unused]] const int* end = inner + outer[dofs[j] + 1];
    for (int i : order) {
      while (*pos < dofs[i]) ++pos;
      assert(pos != end && *pos == dofs[i]);
      add_entry(values, pos - inner, local(i, j));
    }
  }
}

/// Element e's matrix of `form` as the assembler sums it (Local: double or double-double): the
/// space's shared closed form (returned in place), its own closed form, else quadrature on `ev`;
/// closed forms are of unit coefficient and scaled here. `dofs` gets the rows' global indices
/// (closed forms: element_dofs order, read from `table`).
template <class Local>
const Local* element_local(const Space& space, const ElementDofTable* table, int e, const Integrator& form,
                           int quad_degree, ElementValues& ev, Local& local, std::vector<int>& dofs,
                           int components = 1) {
  const auto table_dofs = [&] {
    if (table) {
      dofs.assign(table->begin(e), table->begin(e + 1));
      return;
    }
    space.element_dofs(e, dofs);
    expand_component_dofs(dofs, components, space.dimension());
  };
  const std::optional<BilinearForm> kind = form.closed_form_kind();
  const ClosedForms* closed = kind ? space.closed_forms() : nullptr;
  if (closed) {
    const double c = form.coefficient();
    if (const Local* shared = closed->shared<Local>(e, *kind)) {
      table_dofs();
      if (c == 1.0) return shared;
      local = *shared;
      Integrator::scale(local, c);
      return &local;
    }
    if (closed->element_matrix(e, *kind, local)) {
      table_dofs();
      if (c != 1.0) Integrator::scale(local, c);
      return &local;
    }
  }
  ev.reinit(e, *space.quadrature(e, quad_degree));
  form.element_matrix(ev, local);
  dofs = ev.dofs();
  expand_component_dofs(dofs, components, space.dimension());  // a vector field's unknowns
  return &local;
}

/// Let the space build the closed-form tables `form` will read, outside the element loop.
template <class Local>
void prepare_closed_forms(const Space& space, const Integrator& form) {
  const ClosedForms* closed = space.closed_forms();
  if (closed && form.closed_form_kind()) closed->prepare<Local>(*form.closed_form_kind());
}

}  // namespace

void prepare_extended_element_matrices(const Space& space, const Integrator& form) {
  prepare_closed_forms<DoubleDoubleMatrix>(space, form);
}

const DoubleDoubleMatrix& extended_element_matrix(const Space& space, int e, const Integrator& form, int quad_degree,
                                                  ElementValues& ev, DoubleDoubleMatrix& scratch,
                                                  std::vector<int>& dofs, int components) {
  return *element_local(space, nullptr, e, form, quad_degree, ev, scratch, dofs, components);
}

template <class Local, class Values>
void Assembler::assemble(const Integrator& form, int quad_degree, Values values) const {
  // Blocks of consecutive elements: their matrices are computed in parallel into slots, then each
  // thread adds the columns it owns (an equal share of the dofs), element by element. Every entry
  // receives its contributions in element order whatever the number of threads (bitwise the same
  // matrix), and there are two barriers per block instead of one per colour: colours of a small
  // mesh hold a few dozen elements each, too few to keep two threads busy between barriers.
  keep_eigen_serial();
  // The space's closed forms in the scalar of Local, where it has them (rows in element_dofs
  // order, as the table); quadrature otherwise.
  prepare_closed_forms<Local>(space_, form);
  const int ne = space_.num_elements();
  const int dim = static_cast<int>(pattern_.rows());  // unknowns: components · functions
  using Scalar = typename Local::Scalar;
  constexpr long kBlockBytes = 16L << 20;  // slots of one block: well inside the last-level cache
  const long per_element = std::max<long>(1, static_cast<long>(max_local_) * max_local_ * sizeof(Scalar));
  const int block = static_cast<int>(std::max<long>(1, std::min<long>(ne, std::max<long>(64, kBlockBytes / per_element))));
  std::vector<Local> slots(std::min(block, ne));
  std::vector<const Local*> slot_matrix(slots.size());  // the slot, or a matrix shared by elements
  std::vector<std::vector<int>> slot_dofs(slots.size());
#pragma omp parallel if (worth_threads(ne))
  {
    ElementValues ev(space_, form.flags());
    const int threads = omp_get_num_threads(), me = omp_get_thread_num();
    const int own_first = static_cast<int>(static_cast<long>(dim) * me / threads);
    const int own_last = static_cast<int>(static_cast<long>(dim) * (me + 1) / threads);
    for (int first = 0; first < ne; first += block) {
      const int last = std::min(ne, first + block);
#pragma omp for schedule(dynamic, 8)
      for (int e = first; e < last; ++e) {
        progress_tick();
        slot_matrix[e - first] =
            element_local(space_, &table_, e, form, quad_degree, ev, slots[e - first], slot_dofs[e - first],
                          components_);
      }
      for (int e = first; e < last; ++e)
        scatter_owned_columns(slot_dofs[e - first], *slot_matrix[e - first], pattern_, values, own_first, own_last);
#pragma omp barrier
    }
  }
}

SparseMatrix Assembler::matrix(const Form& form, int quad_degree) const {
  SparseMatrix A = pattern_;
  assemble<Eigen::MatrixXd>(*form, quad_degree, A.valuePtr());
  return A;
}

SplitMatrix Assembler::matrix_extended(const Form& form, int quad_degree) const {
  // Entries summed in double-double: long double sums of h⁻² contributions would round each entry
  // by ≈ 5e-20 of its size, an error the biharmonic system amplifies by h⁻⁴.
  // The pattern copied and the values zeroed by all threads: first touch of a few hundred
  // megabytes, whose page faults cost as much as the copy.
  const Eigen::Index nnz = pattern_.nonZeros();
  SplitMatrix k{SparseMatrix(pattern_.rows(), pattern_.cols()), Eigen::VectorXd(nnz)};
  k.high.resizeNonZeros(nnz);
  std::copy(pattern_.outerIndexPtr(), pattern_.outerIndexPtr() + pattern_.outerSize() + 1, k.high.outerIndexPtr());
  double* hi = k.high.valuePtr();
  double* lo = k.low.data();
  int* inner = k.high.innerIndexPtr();
  const int* pattern_inner = pattern_.innerIndexPtr();
#pragma omp parallel for schedule(static) if (worth_threads(nnz / 1024))
  for (Eigen::Index p = 0; p < nnz; ++p) {
    inner[p] = pattern_inner[p];
    hi[p] = 0.0;
    lo[p] = 0.0;
  }
  assemble<DoubleDoubleMatrix>(*form, quad_degree, SplitValues{hi, lo});
  // Renormalised so that high is each entry rounded to double.
#pragma omp parallel for schedule(static) if (worth_threads(nnz / 1024))
  for (Eigen::Index p = 0; p < nnz; ++p) {
    const DoubleDouble v = DoubleDouble(hi[p], lo[p]) + DoubleDouble(0.0);
    hi[p] = v.hi;
    lo[p] = v.lo;
  }
  return k;
}

Eigen::VectorXd Assembler::load(const ScalarField& f, int quad_degree) const {
  return load(
      [&f](const Eigen::Matrix2Xd& points, Eigen::MatrixXd& values) {
        values.resize(1, points.cols());
        for (Eigen::Index k = 0; k < points.cols(); ++k) values(0, k) = f(points.col(k));
      },
      quad_degree);
}

Eigen::VectorXd Assembler::load(const BatchField& f, int quad_degree) const {
  std::vector<int> all(space_.num_elements());
  std::iota(all.begin(), all.end(), 0);
  return subset_load(space_, all, f, quad_degree);
}

}  // namespace iga
