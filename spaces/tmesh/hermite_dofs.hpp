#pragma once
/// @file
/// The Hermite degrees of freedom of C^r generalized splines over an admissible T-mesh and their
/// numbering (the (V), (E), (C) blocks of hermite_extraction.hpp), with the conditions under which
/// they are a basis of the dual space. The extraction builds the functions dual to them.

#include <vector>

#include "spaces/tmesh/tmesh.hpp"

namespace iga {

struct HermiteDofs {
  int n = 0, r = 0;
  /// First DOF of each vertex ((r+1)² each; -1 at T-junctions, which carry none).
  std::vector<int> vertex_base;
  /// First DOF of each composite edge ((r+1) (last_order(e) - r) each).
  std::vector<int> edge_base;
  /// First DOF of each cell ((n-2r-1)² each).
  std::vector<int> cell_base;
  int dimension = 0;
  /// Last one-sided tangential order k_a of the DOFs of edge e.
  int last_order(const CompositeEdge& e) const { return n - r - 3 + e.d; }
};

/// Number the DOFs of C^r on `mesh`: vertices, then edges, then cells. Throws std::invalid_argument
/// when the mesh is not admissible (reason included), the section spaces differ in n, an edge has
/// d_e = 1, or n is too small (n >= 2r+1, and n >= 2r+3 when some edge has d_e = 0).
HermiteDofs number_hermite_dofs(const TMesh& mesh, int r);

}  // namespace iga
