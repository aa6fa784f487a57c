#pragma once
/// @file
/// How the solution file draws the elements of a space: which reference points each element is
/// sampled at (the nodes of one Lagrange cell of the space's degree, of a uniform subdivision into
/// such cells, or Space::sample_cell's linear sub-cells), where they lie in physical space, which of
/// them coincide (written once), and the VTK cells over the merged points. The fields drawn on it
/// are the writer's job (vtk_writer.hpp).

#include <cstdint>
#include <map>
#include <memory>
#include <utility>
#include <vector>

#include "spaces/space.hpp"

namespace iga {

struct ElementDrawing {
  /// The space's elements are single polynomials drawn exactly as Lagrange cells of its degree.
  bool lagrange = false;
  /// Element e is sampled at the points of *rule[e]. Evaluators may cache tables keyed by a rule's
  /// address, so every distinct set of sample points has one rule, alive with the drawing.
  std::vector<const QuadratureRule*> rule;
  /// Element e owns the unmerged points [offset[e], offset[e+1]).
  std::vector<std::int64_t> offset;
  /// Physical coordinates of the unmerged points (x, y, z each; z = 0 in the plane).
  std::vector<double> xyz;
  /// The point of the file each unmerged point is, and whether it is the first copy of that point
  /// (the one that writes its values).
  std::vector<std::int64_t> merged_id;
  std::vector<char> owner;
  std::int64_t num_points = 0;  ///< points of the file (after merging)
  /// The VTK cells over the merged points, in element order: cell c is of VTK type cell_types[c],
  /// on the points connectivity[cell_offsets[c] .. cell_offsets[c+1]), and draws cell_element[c].
  std::vector<std::int64_t> cell_offsets, connectivity;
  std::vector<unsigned char> cell_types;
  std::vector<int> cell_element;

  std::int64_t num_unmerged() const { return offset.back(); }

  /// The distinct point sets (rules and the cells over them), keyed by cell type and points.
  std::map<std::vector<double>, std::pair<std::shared_ptr<QuadratureRule>, std::vector<std::vector<int>>>> pieces;
};

/// The drawing of every element of `space`: with `lagrange`, single-polynomial elements as one
/// Lagrange cell of the space's degree and the others as `divisions`² such cells (0: linear
/// sub-cells); else (or where the degree is outside 1..10) Space::sample_cell's linear sub-cells
/// with `samples` per edge. Points are evaluated in parallel with one progress_tick() per element
/// (in the caller's progress phase). Throws std::logic_error for sample cells that are not all
/// triangles or all quadrilaterals, and what the space's evaluator throws.
ElementDrawing draw_elements(const Space& space, bool lagrange, int divisions, int samples);

}  // namespace iga
