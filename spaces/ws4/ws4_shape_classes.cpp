#include "spaces/ws4/ws4_shape_classes.hpp"

#include <bit>
#include <map>

namespace iga::ws4 {

ElementDofGeometry translated_to_origin(const ElementDofGeometry& geometry) {
  ElementDofGeometry g = geometry;
  g.corner[1] = geometry.corner[1] - geometry.corner[0];
  g.corner[2] = geometry.corner[2] - geometry.corner[0];
  g.corner[0] = Point2::Zero();
  return g;
}

namespace {

/// Every number of a translated geometry as its bits (so -0 and 0 differ: no rounding question).
using Key = std::array<std::uint64_t, 4 + 12 + 3 + 3 + 3>;

Key shape_key(const ElementDofGeometry& g) {
  Key key{};
  std::size_t k = 0;
  auto put = [&](double v) { key[k++] = std::bit_cast<std::uint64_t>(v); };
  for (int a = 1; a < 3; ++a) put(g.corner[a].x()), put(g.corner[a].y());
  for (int a = 0; a < 3; ++a)
    for (int i = 0; i < 4; ++i) put(g.frame[a](i));
  for (int a = 0; a < 3; ++a) {
    put(g.vertex_scale[a]);
    put(g.edge_scale[a]);
    key[k++] = g.edge_reversed[a] ? 1 : 0;
  }
  return key;
}

}  // namespace

ShapeClasses group_by_shape(const std::vector<ElementDofGeometry>& translated) {
  ShapeClasses out;
  out.of_element.resize(translated.size());
  std::map<Key, int> index;
  for (std::size_t t = 0; t < translated.size(); ++t) {
    const auto [it, fresh] = index.emplace(shape_key(translated[t]), out.size());
    if (fresh) {
      out.representative.push_back(static_cast<int>(t));
      out.count.push_back(0);
    }
    out.of_element[t] = it->second;
    ++out.count[it->second];
  }
  return out;
}

}  // namespace iga::ws4
