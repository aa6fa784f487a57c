#pragma once
/// @file
/// The singular case of an essential-data projection (boundary_projection.hpp): the boundary
/// traces of the functions the data see are linearly dependent (G1 and 4-split vertex functions at
/// corners and crossings). An independent subset is constrained; each other function stays free
/// after subtracting its trace's combination of the constrained ones (a local change of basis).

#include <Eigen/Core>
#include <vector>

#include "assembly/boundary_conditions.hpp"
#include "assembly/sparsity.hpp"

namespace iga {

/// M (m x m): the Gram matrix of the boundary data of the functions `order` (local index =
/// position), with dependent columns; r its right-hand side; `local_of` as in
/// solve_boundary_projection. Fills c.values, c.constrained, c.free and c.basis_change. Sparse but
/// for small clusters: the dependencies are local, but there are some at every corner, so m grows
/// with the boundary — a dense QR of M cost O(m³) time and m² memory on every rank and was refused
/// above 6 000 functions (the 4-split at 1.3·10⁶ DOFs has 6 395).
void split_dependent_traces(const SparseMatrix& M, const Eigen::VectorXd& r, const std::vector<int>& order,
                            const std::vector<int>& local_of, Constraints& c);

}  // namespace iga
