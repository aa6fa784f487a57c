#pragma once
// Meshes the WS4 tests share.

#include <random>

#include "spaces/ws4/triangulation.hpp"

namespace iga::test {

/// The N x N unit-square mesh with interior vertices moved by up to ±15% of h (fixed seed).
inline ws4::Triangulation perturbed_square(int n, unsigned seed) {
  ws4::Triangulation mesh = ws4::Triangulation::rectangle(n, n, Point2(0, 0), Point2(1, 1));
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u(-0.15 / n, 0.15 / n);
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    const Point2 x = mesh.vertices()[v];
    if (x.x() > 0 && x.x() < 1 && x.y() > 0 && x.y() < 1) mesh.move_vertex(v, x + Point2(u(gen), u(gen)));
  }
  return mesh;
}

}  // namespace iga::test
