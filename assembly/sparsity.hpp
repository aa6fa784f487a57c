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

/// The table of every element, or of `elements` only (in that order) when given.
ElementDofTable collect_element_dofs(const Space& space, const std::vector<int>* elements = nullptr);

/// A compressed matrix with explicit zeros at every (i, j) such that functions i and j are active
/// on a common element; inner indices sorted within each column.
SparseMatrix sparsity_pattern(const ElementDofTable& table, int dimension);

}  // namespace iga
