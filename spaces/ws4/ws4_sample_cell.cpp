#include "spaces/ws4/ws4_sample_cell.hpp"

#include "spaces/ws4/ws4_split.hpp"

namespace iga::ws4 {

SampleCell split_sample_cell(int resolution) {
  const Ws4Split& split = Ws4Split::reference();
  SampleCell s;
  const int m = resolution / 8;
  if (m <= 1) {
    for (int v = 0; v < static_cast<int>(split.vertices().size()); ++v) s.points.push_back(split.vertex_point(v));
    for (const auto& t : split.fan_triangles()) s.cells.push_back({t[0], t[1], t[2]});
    return s;
  }
  for (const auto& t : split.fan_triangles()) {
    const Point2 a = split.vertex_point(t[0]), b = split.vertex_point(t[1]), c = split.vertex_point(t[2]);
    append_triangle_grid(s, a, b, c, m);
  }
  return s;
}

}  // namespace iga::ws4
