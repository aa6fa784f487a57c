#include "mesh/validate_planar_mesh.hpp"

#include <algorithm>
#include <map>
#include <numeric>

#include "config/config_node.hpp"
#include "config/errors.hpp"
#include "config/utf8.hpp"
#include "config/text_excerpt.hpp"
#include "mesh/coincident_points.hpp"
#include "mesh/planar_vectors.hpp"

namespace iga {

namespace {

using Edge = std::array<int, 2>;

[[noreturn]] void reject(const PlanarMesh& mesh, const std::string& message) {
  throw InputError(mesh.source + ": " + message);
}

int num_vertices(const PlanarMesh& mesh) { return static_cast<int>(mesh.vertices.size()); }
int num_cells(const PlanarMesh& mesh) { return static_cast<int>(mesh.cells.size()); }

std::string describe_vertex(const PlanarMesh& mesh, int v) {
  return "vertex " + std::to_string(v) + " " + describe_point(mesh.vertices[v]);
}

void check_cell_kinds_and_ids(const PlanarMesh& mesh, const AllowedCells& allowed) {
  const std::string who = allowed.space.empty() ? "this space" : "the " + allowed.space + " space";
  for (int c = 0; c < num_cells(mesh); ++c) {
    const std::vector<int>& cell = mesh.cells[c];
    if (cell.size() != 3 && cell.size() != 4)
      reject(mesh, describe_cell(mesh, c) + " has " + std::to_string(cell.size()) +
                       " vertices; only triangles and quadrilaterals are supported");
    for (int v : cell)
      if (v < 0 || v >= num_vertices(mesh))
        reject(mesh, describe_cell(mesh, c) + " refers to vertex " + std::to_string(v) + ", but the mesh has " +
                         std::to_string(num_vertices(mesh)) + " vertices");
    if (cell.size() == 3 && !allowed.triangles)
      reject(mesh, describe_cell(mesh, c) + " is a triangle; " + who + " needs quadrilaterals");
    if (cell.size() == 4 && !allowed.quads)
      reject(mesh, describe_cell(mesh, c) + " is a quadrilateral; " + who + " needs triangles");
    for (std::size_t i = 0; i < cell.size(); ++i)
      for (std::size_t j = i + 1; j < cell.size(); ++j)
        if (cell[i] == cell[j])
          reject(mesh, describe_cell(mesh, c) + " uses vertex " + std::to_string(cell[i]) + " twice");
  }
}

double longest_edge(const PlanarMesh& mesh, int c) {
  const std::vector<int>& cell = mesh.cells[c];
  double h = 0.0;
  for (std::size_t k = 0; k < cell.size(); ++k)
    h = std::max(h, (mesh.vertices[cell[(k + 1) % cell.size()]] - mesh.vertices[cell[k]]).norm());
  return h;
}

void check_cell_shapes(const PlanarMesh& mesh) {
  for (int c = 0; c < num_cells(mesh); ++c) {
    const std::vector<int>& cell = mesh.cells[c];
    const double h = longest_edge(mesh, c), area = 0.5 * twice_signed_area(mesh, c);
    if (std::abs(area) <= mesh_tolerance * h * h)
      reject(mesh, describe_cell(mesh, c) + " is degenerate (area " + format_number(area) + ", longest edge " +
                       format_number(h) + ")");
    if (area < 0.0)
      reject(mesh, describe_cell(mesh, c) + " is clockwise (inverted); list its vertices counterclockwise");
    if (cell.size() != 4) continue;
    // The bilinear map's Jacobian at corner k is the cross product of the two edges leaving it;
    // a non-positive one means a folded (bow-tie) or non-convex quadrilateral.
    for (int k = 0; k < 4; ++k) {
      const Eigen::Vector2d& p = mesh.vertices[cell[k]];
      const double det = cross(mesh.vertices[cell[(k + 1) % 4]] - p, mesh.vertices[cell[(k + 3) % 4]] - p);
      if (det <= mesh_tolerance * h * h)
        reject(mesh, describe_cell(mesh, c) + " is folded or not convex at corner " + describe_point(p) +
                         " (bilinear Jacobian " + format_number(det) + " <= 0)");
    }
  }
}

/// Cells that are valid but so thin that the spaces built on them are singular in floating point
/// (their boundary traces dependent, their systems unsolvable): a corner's cross product below
/// mesh_shape_tolerance x (longest edge)². Checked after the topology, whose messages say more.
void check_cell_quality(const PlanarMesh& mesh) {
  for (int c = 0; c < num_cells(mesh); ++c) {
    const std::vector<int>& cell = mesh.cells[c];
    const std::size_t n = cell.size();
    const double h = longest_edge(mesh, c);
    double shortest = h;
    for (std::size_t k = 0; k < n; ++k)
      shortest = std::min(shortest, (mesh.vertices[cell[(k + 1) % n]] - mesh.vertices[cell[k]]).norm());
    for (std::size_t k = 0; k < n; ++k) {
      const Eigen::Vector2d& p = mesh.vertices[cell[k]];
      const double ratio = cross(mesh.vertices[cell[(k + 1) % n]] - p, mesh.vertices[cell[(k + n - 1) % n]] - p) / (h * h);
      if (ratio < mesh_shape_tolerance)
        reject(mesh, describe_cell(mesh, c) + " is nearly degenerate at corner " + describe_point(p) +
                         ": its edges there span " + format_number(ratio) + " x (longest edge)², less than " +
                         format_number(mesh_shape_tolerance) + " (shortest edge " + format_number(shortest) +
                         ", longest " + format_number(h) +
                         "); a cell this thin or with vertices this close makes the space singular in floating point");
    }
  }
}

void check_coincident_vertices(const PlanarMesh& mesh) {
  if (mesh.vertices.empty()) return;
  Eigen::Vector2d lo = mesh.vertices[0], hi = lo;
  for (const auto& x : mesh.vertices) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  std::vector<int> ids(mesh.vertices.size());
  std::iota(ids.begin(), ids.end(), 0);
  const double eps = mesh_tolerance * (hi - lo).norm();
  if (const auto pair = find_coincident_points(mesh.vertices, ids, eps, Closeness::every_coordinate))
    reject(mesh, describe_vertex(mesh, pair->first) + " and vertex " + std::to_string(pair->second) +
                     " coincide; merge duplicate nodes (cells meeting there are not connected)");
}

std::string describe_edge(const PlanarMesh& mesh, const Edge& e) {
  return "edge " + describe_point(mesh.vertices[e[0]]) + "-" + describe_point(mesh.vertices[e[1]]);
}

/// Directed uses of every undirected edge: which cells traverse it, and in which direction.
struct EdgeUse {
  std::vector<int> cells;
  std::vector<bool> forward;  ///< traversed from min to max vertex id
};

std::map<Edge, EdgeUse> edge_uses(const PlanarMesh& mesh) {
  std::map<Edge, EdgeUse> uses;
  for (int c = 0; c < num_cells(mesh); ++c) {
    const std::vector<int>& cell = mesh.cells[c];
    for (std::size_t k = 0; k < cell.size(); ++k) {
      const int a = cell[k], b = cell[(k + 1) % cell.size()];
      EdgeUse& use = uses[{std::min(a, b), std::max(a, b)}];
      use.cells.push_back(c);
      use.forward.push_back(a < b);
    }
  }
  return uses;
}

void check_edges_and_boundary(const PlanarMesh& mesh, const std::map<Edge, EdgeUse>& uses) {
  std::vector<int> boundary_count(mesh.vertices.size(), 0);
  for (const auto& [edge, use] : uses) {
    if (use.cells.size() > 2)
      reject(mesh, describe_edge(mesh, edge) + " is shared by " + std::to_string(use.cells.size()) + " cells (" +
                       std::to_string(use.cells[0]) + ", " + std::to_string(use.cells[1]) + ", " +
                       std::to_string(use.cells[2]) + "): the mesh is not a manifold");
    if (use.cells.size() == 2 && use.forward[0] == use.forward[1])
      reject(mesh, describe_cell(mesh, use.cells[0]) + " and " + describe_cell(mesh, use.cells[1]) +
                       " lie on the same side of their common " + describe_edge(mesh, edge) +
                       ": the mesh folds over itself");
    if (use.cells.size() == 1) {
      ++boundary_count[edge[0]];
      ++boundary_count[edge[1]];
    }
  }
  for (int v = 0; v < num_vertices(mesh); ++v)
    if (boundary_count[v] > 2)
      reject(mesh, "the boundary touches itself at " + describe_vertex(mesh, v) + " (" +
                       std::to_string(boundary_count[v]) +
                       " boundary edges meet there); cells must be connected through edges");
}

void check_referenced_vertices(const PlanarMesh& mesh) {
  std::vector<bool> used(mesh.vertices.size(), false);
  for (const auto& cell : mesh.cells)
    for (int v : cell) used[v] = true;
  for (int v = 0; v < num_vertices(mesh); ++v)
    if (!used[v]) reject(mesh, describe_vertex(mesh, v) + " belongs to no cell");
}

void check_boundary_groups(const PlanarMesh& mesh, const std::map<Edge, EdgeUse>& uses) {
  for (const auto& [name, edges] : mesh.boundary_groups) {
    // Group names become boundary part names in messages, VTK files and summary.json.
    if (const auto bad = invalid_utf8_offset(name))
      reject(mesh, "a boundary group name is not UTF-8 text (" + describe_byte(name, *bad) + " at byte " +
                       std::to_string(*bad + 1) + " of the name)");
    for (const Edge& e : edges) {
      const bool known = e[0] >= 0 && e[0] < num_vertices(mesh) && e[1] >= 0 && e[1] < num_vertices(mesh);
      if (!known) reject(mesh, "boundary group " + quoted_excerpt(name) + " refers to a vertex that does not exist");
      const auto it = uses.find({std::min(e[0], e[1]), std::max(e[0], e[1])});
      if (it == uses.end() || it->second.cells.size() != 1)
        reject(mesh, "boundary group " + quoted_excerpt(name) + " has " + describe_edge(mesh, e) +
                         ", which is not a boundary edge of the mesh");
    }
  }
}

}  // namespace

void validate_planar_mesh(const PlanarMesh& mesh, const AllowedCells& allowed) {
  if (mesh.cells.empty()) reject(mesh, "the mesh has no cells");
  check_cell_kinds_and_ids(mesh, allowed);
  check_cell_shapes(mesh);
  check_coincident_vertices(mesh);
  const std::map<Edge, EdgeUse> uses = edge_uses(mesh);
  check_edges_and_boundary(mesh, uses);
  check_referenced_vertices(mesh);
  check_boundary_groups(mesh, uses);
  check_cell_quality(mesh);
}

}  // namespace iga
