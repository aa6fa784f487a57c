#include "spaces/ws4/ws4_sample_cell.hpp"

#include "spaces/ws4/ws4_split.hpp"
#include "spaces/ws4/ws4_space.hpp"

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
    const int first = static_cast<int>(s.points.size());
    // Row j holds m + 1 - j points; index of (i, j) is first + offset(j) + i.
    std::vector<int> offset(m + 2, first);
    for (int j = 0; j <= m; ++j) {
      offset[j + 1] = offset[j] + (m + 1 - j);
      for (int i = 0; i <= m - j; ++i) s.points.push_back(a + (double(i) / m) * (b - a) + (double(j) / m) * (c - a));
    }
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m - j; ++i) {
        const int p = offset[j] + i, q = p + 1, r = offset[j + 1] + i;
        s.cells.push_back({p, q, r});
        if (i + 1 < m - j) s.cells.push_back({q, r + 1, r});
      }
  }
  return s;
}

SampleCell Ws4Space::sample_cell(int /*element*/, int resolution) const { return split_sample_cell(resolution); }

}  // namespace iga::ws4
