#pragma once
/// @file
/// What does not change while a space is used: the global indices active on every element and the
/// sparsity pattern of its matrices.

#include <Eigen/SparseCore>
#include <algorithm>
#include <cassert>
#include <vector>

#include "spaces/space.hpp"

namespace iga {

using SparseMatrix = Eigen::SparseMatrix<double>;  // column-major, int indices (CHOLMOD, UMFPACK)

/// Element -> active global indices, in compressed rows: dofs[offsets[e] .. offsets[e+1]).
struct ElementDofTable {
  std::vector<int> offsets;
  std::vector<int> dofs;
  int num_elements() const { return static_cast<int>(offsets.size()) - 1; }
  int size(int e) const { return offsets[e + 1] - offsets[e]; }
  const int* begin(int e) const { return dofs.data() + offsets[e]; }
};

ElementDofTable collect_element_dofs(const Space& space);

/// A compressed matrix with explicit zeros at every (i, j) such that functions i and j are active
/// on a common element; inner indices sorted within each column.
SparseMatrix sparsity_pattern(const ElementDofTable& table, int dimension);

/// Add the local matrix `local` (rows and columns in the order of `dofs`) into `values`, an array
/// aligned with the value array of `pattern`, which must hold every entry (sparsity_pattern).
/// Templated so that double matrices and long double value arrays share the one scatter loop.
template <class Local, class Value>
void scatter_add_values(const std::vector<int>& dofs, const Local& local, const SparseMatrix& pattern, Value* values) {
  const int n = static_cast<int>(dofs.size());
  const int* outer = pattern.outerIndexPtr();
  const int* inner = pattern.innerIndexPtr();
  for (int j = 0; j < n; ++j) {
    const int* first = inner + outer[dofs[j]];
    const int* last = inner + outer[dofs[j] + 1];
    for (int i = 0; i < n; ++i) {
      const int* pos = std::lower_bound(first, last, dofs[i]);
      assert(pos != last && *pos == dofs[i]);
      values[pos - inner] += local(i, j);
    }
  }
}

/// Add the local matrix `local` (rows and columns in the order of `dofs`) into `matrix`, whose
/// pattern must already hold every entry (sparsity_pattern).
inline void scatter_add(const std::vector<int>& dofs, const Eigen::MatrixXd& local, SparseMatrix& matrix) {
  scatter_add_values(dofs, local, matrix, matrix.valuePtr());
}

}  // namespace iga
