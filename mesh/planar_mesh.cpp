#include "mesh/planar_mesh.hpp"

#include <algorithm>

#include "config/config_node.hpp"
#include "config/errors.hpp"

namespace iga {

double twice_signed_area(const PlanarMesh& mesh, int c) {
  const std::vector<int>& cell = mesh.cells[c];
  double sum = 0.0;
  for (std::size_t k = 0; k < cell.size(); ++k) {
    const Eigen::Vector2d& p = mesh.vertices[cell[k]];
    const Eigen::Vector2d& q = mesh.vertices[cell[(k + 1) % cell.size()]];
    sum += p.x() * q.y() - p.y() * q.x();
  }
  return sum;
}

void orient_cells_counterclockwise(PlanarMesh& mesh) {
  for (int c = 0; c < static_cast<int>(mesh.cells.size()); ++c)
    if (twice_signed_area(mesh, c) < 0.0) std::reverse(mesh.cells[c].begin() + 1, mesh.cells[c].end());
}

void orient_consistently_counterclockwise(PlanarMesh& mesh) {
  int first = -1;  // the first cell with an orientation (degenerate cells are left to validation)
  for (int c = 0; c < static_cast<int>(mesh.cells.size()); ++c) {
    const double area = twice_signed_area(mesh, c);
    if (area == 0.0) continue;
    if (first < 0) {
      first = c;
    } else if ((area > 0.0) != (twice_signed_area(mesh, first) > 0.0)) {
      const auto sense = [&](int cell) {
        return twice_signed_area(mesh, cell) > 0.0 ? std::string("counterclockwise") : std::string("clockwise");
      };
      throw InputError(mesh.source + ": " + describe_cell(mesh, c) + " is listed " + sense(c) + ", but " +
                       describe_cell(mesh, first) + " is listed " + sense(first) +
                       ": inconsistent orientation (list the vertices of every cell in the same sense)");
    }
  }
  orient_cells_counterclockwise(mesh);
}

std::vector<std::array<int, 2>> boundary_edges(const PlanarMesh& mesh) {
  std::map<std::array<int, 2>, int> uses;  // undirected edge (min, max) -> number of cells
  for (const auto& cell : mesh.cells)
    for (std::size_t k = 0; k < cell.size(); ++k) {
      const int a = cell[k], b = cell[(k + 1) % cell.size()];
      ++uses[{std::min(a, b), std::max(a, b)}];
    }
  std::vector<std::array<int, 2>> result;
  for (const auto& cell : mesh.cells)
    for (std::size_t k = 0; k < cell.size(); ++k) {
      const int a = cell[k], b = cell[(k + 1) % cell.size()];
      if (uses[{std::min(a, b), std::max(a, b)}] == 1) result.push_back({a, b});
    }
  return result;
}

std::string describe_point(const Eigen::Vector2d& x) {
  // Appended piece by piece: "(" + std::string&& trips GCC 12's false -Wrestrict warning.
  std::string s = "(";
  s += format_number(x.x());
  s += ", ";
  s += format_number(x.y());
  return s + ")";
}

std::string describe_cell(const PlanarMesh& mesh, int c) {
  const std::vector<int>& cell = mesh.cells[c];
  std::string s = "cell " + std::to_string(c) + " (";
  if (c < static_cast<int>(mesh.cell_origins.size())) s += mesh.cell_origins[c] + ": ";
  s += cell.size() == 3   ? std::string("triangle")
       : cell.size() == 4 ? std::string("quadrilateral")
                          : std::to_string(cell.size()) + "-gon";
  for (std::size_t k = 0; k < cell.size(); ++k) {
    const int v = cell[k];
    const bool known = v >= 0 && v < static_cast<int>(mesh.vertices.size());
    s += k ? ", " : " ";
    s += known ? describe_point(mesh.vertices[v]) : "vertex " + std::to_string(v) + "?";
  }
  return s + ")";
}

}  // namespace iga
