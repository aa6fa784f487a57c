#pragma once
/// @file
/// T-mesh of axis-aligned rectangular cells on exact integer (dyadic lattice) coordinates, with the
/// topology that generalized splines over T-meshes need (notes §1.3, §7): vertices, T-junctions by
/// the corrected rule (a vertex is a T-junction iff it lies in the interior of a side of some cell,
/// which keeps the dimension formula right on L-shapes), composite edges with their cells Delta_e
/// and d_e, the regularity and cycle checks, and the dimension formula (21).
///
/// Physical coordinates: x = origin.x + X * unit.x, y = origin.y + Y * unit.y for lattice (X, Y).

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <string>
#include <tuple>
#include <vector>

#include "spaces/tmesh/section_space.hpp"

namespace iga {

/// A cell [x0, x1] x [y0, y1] in lattice units; section_s / section_t index TMesh::sections().
struct TCell {
  std::int64_t x0 = 0, x1 = 0, y0 = 0, y1 = 0;
  int section_s = 0, section_t = 0;
};

/// What fixes the one-dimensional basis of a cell side: (section, axis 0 = x or 1 = y, lattice
/// length). The axis counts because a lattice unit may have different physical lengths in x and
/// y, and non-polynomial sections depend on the physical length.
using CellSideKey = std::tuple<int, int, std::int64_t>;
inline CellSideKey side_key_x(const TCell& c) { return {c.section_s, 0, c.x1 - c.x0}; }
inline CellSideKey side_key_y(const TCell& c) { return {c.section_t, 1, c.y1 - c.y0}; }

struct TVertex {
  std::int64_t x = 0, y = 0;
  bool t_junction = false;  ///< lies in the interior of a side of some cell
  bool boundary = false;    ///< some quadrant around it is not covered
  int host_edge = -1;       ///< for a T-junction: the composite edge containing it in its interior
};

/// A maximal segment whose interior vertices are all T-junctions.
struct CompositeEdge {
  bool horizontal = true;
  std::int64_t line = 0;         ///< y (horizontal) or x (vertical)
  std::int64_t lo = 0, hi = 0;   ///< extent along the edge
  int v_lo = -1, v_hi = -1;      ///< end vertices
  std::vector<int> t_junctions;  ///< interior vertices, increasing along the edge
  std::vector<int> cells;        ///< Delta_e: cells with a side overlapping the edge
  int d = 2;                     ///< dim of the common non-polynomial part (0, 1, 2)
  std::vector<int> deps;         ///< edges whose processing gives the jets of its T-junction ends
};

class TMesh {
 public:
  /// Cells in lattice units, their section spaces, and the lattice-to-physical map. Builds the
  /// topology; throws std::invalid_argument if cells overlap or a section index is invalid.
  TMesh(std::vector<TCell> cells, std::vector<SectionSpec> sections, Eigen::Vector2d origin, Eigen::Vector2d unit);

  /// nx x ny tensor mesh of [lo, hi] with one section space everywhere.
  static TMesh rectangle(Eigen::Vector2d lo, Eigen::Vector2d hi, int nx, int ny, const SectionSpec& section);
  /// The rectangle [lo, hi] without its upper-right quarter, as a (nx x ny) grid minus the cells of
  /// that quarter (nx, ny even).
  static TMesh l_shape(Eigen::Vector2d lo, Eigen::Vector2d hi, int nx, int ny, const SectionSpec& section);

  /// Split the given cells into four children (dyadic); children inherit the sections.
  TMesh refined(const std::vector<int>& cells) const;
  /// The cells of refined(): each of `which` replaced by its four children, in place. Throws
  /// std::invalid_argument when a cell is one lattice unit wide. Several refinements of cells
  /// alone, then one TMesh, skip the topology of the meshes in between.
  static std::vector<TCell> split_cells(const std::vector<TCell>& cells, const std::vector<int>& which);
  /// The same cells (and topology) with other section spaces: `cell_sections[c]` = (s, t) indices
  /// into `sections`. Only d_e is recomputed. Throws std::invalid_argument on a bad index.
  TMesh with_sections(const std::vector<std::array<int, 2>>& cell_sections, std::vector<SectionSpec> sections) const;
  /// Split every cell.
  TMesh refined_uniformly() const;

  const std::vector<TCell>& cells() const { return cells_; }
  const std::vector<SectionSpec>& sections() const { return sections_; }
  const std::vector<TVertex>& vertices() const { return vertices_; }
  const std::vector<CompositeEdge>& edges() const { return edges_; }
  int num_cells() const { return static_cast<int>(cells_.size()); }
  /// Composite edge containing side `side` (0 bottom, 1 right, 2 top, 3 left) of `cell`.
  int side_edge(int cell, int side) const { return side_edge_[4 * cell + side]; }
  /// True when side `side` of `cell` lies on the domain boundary (no cell on its other side).
  bool side_on_boundary(int cell, int side) const { return side_boundary_[4 * cell + side]; }
  /// True when some cell side is only partly on the boundary (e.g. a re-entrant corner inside a
  /// side); such a side is reported as interior by side_on_boundary.
  bool has_partial_boundary_sides() const { return partial_boundary_; }
  /// Vertex id at lattice point, -1 if none.
  int vertex_at(std::int64_t x, std::int64_t y) const;

  /// Number of vertices that are not T-junctions (J_NT).
  int num_non_t_vertices() const;
  /// Composite edges in an order where every edge comes after its deps (empty on a cycle).
  const std::vector<int>& edge_order() const { return edge_order_; }
  /// Empty when the mesh is regular and has no cycle of T-junctions; the reason otherwise.
  const std::string& admissibility_problem() const { return problem_; }
  /// Longest chain of dependent composite edges (beta_Delta of the notes).
  int longest_chain() const { return longest_chain_; }

  /// Dimension formula (21) for C^(r1,r2) with n1 = n of the s sections and n2 of the t sections.
  int dimension_formula(int r1, int r2) const;

  /// Physical coordinates of a lattice point.
  Eigen::Vector2d point(std::int64_t x, std::int64_t y) const {
    return {origin_.x() + x * unit_.x(), origin_.y() + y * unit_.y()};
  }
  double width(int cell) const { return (cells_[cell].x1 - cells_[cell].x0) * unit_.x(); }
  double height(int cell) const { return (cells_[cell].y1 - cells_[cell].y0) * unit_.y(); }
  const Eigen::Vector2d& unit() const { return unit_; }
  /// Bounding box in lattice units: x_min, x_max, y_min, y_max.
  std::int64_t bound(int k) const { return bounds_[k]; }

 private:
  void build_topology();
  /// d_e of every composite edge from the sections of its cells.
  void assign_edge_dimensions();

  std::vector<TCell> cells_;
  std::vector<SectionSpec> sections_;
  Eigen::Vector2d origin_, unit_;
  std::int64_t bounds_[4] = {0, 0, 0, 0};

  std::vector<TVertex> vertices_;
  std::vector<std::tuple<std::int64_t, std::int64_t, int>> vertex_index_;  ///< (x, y, id), sorted
  std::vector<CompositeEdge> edges_;
  std::vector<int> side_edge_;
  std::vector<char> side_boundary_;
  std::vector<int> edge_order_;
  std::string problem_;
  int longest_chain_ = 0;
  bool partial_boundary_ = false;
};

}  // namespace iga
