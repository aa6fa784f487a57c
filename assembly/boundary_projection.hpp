#pragma once
/// @file
/// The second half of an essential-data projection (boundary_conditions.hpp, method steps 2–3):
/// the Gram matrix and right-hand side of the boundary least-squares problem, gathered by the
/// caller over the functions its data see, solved into Constraints. Shared by the planar data
/// (impose_essential) and the surface ones (surface_essential.hpp), so that both get the same
/// refinement and the same treatment of dependent traces.

#include <Eigen/SparseCore>
#include <utility>
#include <vector>

#include "assembly/boundary_conditions.hpp"

namespace iga {

/// A function counts as active on an edge when its trace exceeds this fraction of the largest
/// trace there: traces that vanish identically evaluate to round-off.
inline constexpr double kActiveTolerance = 1e-10;

/// `order` lists the global functions seen by the data (local index = position), `local_of` maps
/// each of the `dim` global functions to its local index or −1; `triplets` and `rhs_entries` are
/// the unsummed local Gram matrix and right-hand side. SPD: the constrained coefficients solve it
/// (refined in long double); dependent traces: an independent subset is constrained and the others
/// stay free with a basis change (Constraints::basis_change).
Constraints solve_boundary_projection(int dim, const std::vector<Eigen::Triplet<double>>& triplets,
                                      const std::vector<std::pair<int, double>>& rhs_entries,
                                      const std::vector<int>& order, const std::vector<int>& local_of);

}  // namespace iga
