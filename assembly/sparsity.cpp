#include "assembly/parallel.hpp"
#include "assembly/sparsity.hpp"

#include <algorithm>
#include <cassert>
#include <numeric>

namespace iga {

ElementDofTable collect_element_dofs(const Space& space, const std::vector<int>* elements) {
  const int ne = elements ? static_cast<int>(elements->size()) : space.num_elements();
  std::vector<std::vector<int>> per_element(ne);
#pragma omp parallel for schedule(dynamic, 64) if (worth_threads(ne))
  for (int e = 0; e < ne; ++e) space.element_dofs(elements ? (*elements)[e] : e, per_element[e]);
  ElementDofTable t;
  t.offsets.resize(ne + 1, 0);
  for (int e = 0; e < ne; ++e) t.offsets[e + 1] = t.offsets[e] + static_cast<int>(per_element[e].size());
  t.dofs.resize(t.offsets[ne]);
  for (int e = 0; e < ne; ++e) std::copy(per_element[e].begin(), per_element[e].end(), t.dofs.begin() + t.offsets[e]);
  return t;
}

namespace {

/// Transpose of the element table: for each global index, the elements it is active on.
void elements_of_dofs(const ElementDofTable& t, int dimension, std::vector<int>& offsets, std::vector<int>& elems) {
  offsets.assign(dimension + 1, 0);
  for (int d : t.dofs) ++offsets[d + 1];
  std::partial_sum(offsets.begin(), offsets.end(), offsets.begin());
  elems.resize(t.dofs.size());
  std::vector<int> fill(offsets.begin(), offsets.end() - 1);
  for (int e = 0; e < t.num_elements(); ++e)
    for (const int* d = t.begin(e); d != t.begin(e + 1); ++d) elems[fill[*d]++] = e;
}

}  // namespace

SparseMatrix sparsity_pattern(const ElementDofTable& table, int dimension) {
  std::vector<int> d_off, d_el;
  elements_of_dofs(table, dimension, d_off, d_el);
  // Dofs active on the same elements (those of one vertex, edge or cell, numbered together) have
  // the same column: it is built once, for the first dof of each run, and copied.
  std::vector<int> first_of_run(dimension);
  for (int j = 0; j < dimension; ++j) {
    const bool same = j > 0 && d_off[j + 1] - d_off[j] == d_off[j] - d_off[j - 1] &&
                      std::equal(d_el.begin() + d_off[j], d_el.begin() + d_off[j + 1], d_el.begin() + d_off[j - 1]);
    first_of_run[j] = same ? first_of_run[j - 1] : j;
  }
  std::vector<std::vector<int>> columns(dimension);
#pragma omp parallel if (worth_threads(dimension))
  {
    std::vector<char> seen(dimension, 0);  // per-thread marker, reset after each column
#pragma omp for schedule(dynamic, 256)
    for (int j = 0; j < dimension; ++j) {
      if (first_of_run[j] != j) continue;
      std::vector<int>& col = columns[j];
      for (int k = d_off[j]; k < d_off[j + 1]; ++k) {
        const int e = d_el[k];
        for (const int* d = table.begin(e); d != table.begin(e + 1); ++d)
          if (!seen[*d]) {
            seen[*d] = 1;
            col.push_back(*d);
          }
      }
      for (int i : col) seen[i] = 0;
      std::sort(col.begin(), col.end());
    }
  }
  SparseMatrix A(dimension, dimension);
  std::size_t nnz = 0;
  for (int j = 0; j < dimension; ++j) nnz += columns[first_of_run[j]].size();
  A.resizeNonZeros(static_cast<Eigen::Index>(nnz));
  int* outer = A.outerIndexPtr();
  int* inner = A.innerIndexPtr();
  outer[0] = 0;
  for (int j = 0; j < dimension; ++j) {
    const std::vector<int>& col = columns[first_of_run[j]];
    std::copy(col.begin(), col.end(), inner + outer[j]);
    outer[j + 1] = outer[j] + static_cast<int>(col.size());
  }
  std::fill(A.valuePtr(), A.valuePtr() + nnz, 0.0);
  return A;
}

}  // namespace iga
