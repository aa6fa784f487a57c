#include "spaces/ws4/ws4_split.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <stdexcept>

namespace iga::ws4 {

namespace {

Triple cross(const Triple& a, const Triple& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

long long dot(const Triple& a, const Triple& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

Triple divide_gcd(Triple t) {
  const long long g = std::gcd(std::gcd(std::llabs(t[0]), std::llabs(t[1])), std::llabs(t[2]));
  if (g > 1)
    for (long long& v : t) v /= g;
  return t;
}

/// Line normal form: gcd 1, first nonzero entry positive.
Triple normal_line(Triple t) {
  t = divide_gcd(t);
  const long long lead = t[0] != 0 ? t[0] : (t[1] != 0 ? t[1] : t[2]);
  if (lead < 0)
    for (long long& v : t) v = -v;
  return t;
}

Point2 to_point(const Triple& b) {
  const double s = static_cast<double>(b[0] + b[1] + b[2]);
  return Point2(b[1] / s, b[2] / s);
}

double cross2(const Point2& a, const Point2& b) { return a.x() * b.y() - a.y() * b.x(); }

// Generic directions for the one-sided rule: not along any split line (whose directions are
// rational with small denominators).
const Point2 kInterior(0.3137, 0.2718);
const Point2 kSecond(0.2718, -0.1414);

}  // namespace

const std::array<Triple, 12>& Ws4Split::boundary_points() {
  static const std::array<Triple, 12> pts = {{{4, 0, 0}, {0, 4, 0}, {0, 0, 4},  // p1 p2 p3
                                              {3, 1, 0}, {2, 2, 0}, {1, 3, 0},  // q31 q3 q32
                                              {0, 3, 1}, {0, 2, 2}, {0, 1, 3},  // q12 q1 q13
                                              {3, 0, 1}, {2, 0, 2}, {1, 0, 3}}};  // q21 q2 q23
  return pts;
}

Point2 Ws4Split::boundary_point(int k) { return to_point(boundary_points().at(k)); }

Point2 Ws4Split::vertex_point(int v) const { return to_point(vertices_.at(v)); }

const Ws4Split& Ws4Split::reference() {
  static const Ws4Split split;  // thread-safe initialisation (C++11 magic statics)
  return split;
}

Ws4Split::Ws4Split() {
  // Lines: the three edges first, then every other line through two boundary points.
  lines_ = {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}};
  const auto& bp = boundary_points();
  for (int i = 0; i < 12; ++i)
    for (int j = i + 1; j < 12; ++j) {
      const Triple l = normal_line(cross(bp[i], bp[j]));
      if (std::find(lines_.begin(), lines_.end(), l) == lines_.end()) lines_.push_back(l);
    }

  // Vertices: intersections of two lines inside the closed triangle.
  for (size_t i = 0; i < lines_.size(); ++i)
    for (size_t j = i + 1; j < lines_.size(); ++j) {
      Triple v = cross(lines_[i], lines_[j]);
      const long long s = v[0] + v[1] + v[2];
      if (s == 0) continue;  // parallel lines
      if (s < 0)
        for (long long& c : v) c = -c;
      if (v[0] < 0 || v[1] < 0 || v[2] < 0) continue;
      v = divide_gcd(v);
      if (std::find(vertices_.begin(), vertices_.end(), v) == vertices_.end()) vertices_.push_back(v);
    }
  for (const Triple& v : vertices_) {
    int n = 0;
    for (const Triple& l : lines_) n += dot(l, v) == 0;
    lines_through_.push_back(n);
  }

  // Segments: consecutive vertices along each line.
  const int nv = static_cast<int>(vertices_.size());
  std::vector<std::vector<int>> neighbours(nv);
  for (const Triple& l : lines_) {
    std::vector<int> on;
    for (int v = 0; v < nv; ++v)
      if (dot(l, vertices_[v]) == 0) on.push_back(v);
    const Point2 dir = vertex_point(on.back()) - vertex_point(on.front());
    std::sort(on.begin(), on.end(), [&](int a, int b) { return vertex_point(a).dot(dir) < vertex_point(b).dot(dir); });
    for (size_t k = 0; k + 1 < on.size(); ++k) {
      segments_.push_back({on[k], on[k + 1]});
      neighbours[on[k]].push_back(on[k + 1]);
      neighbours[on[k + 1]].push_back(on[k]);
    }
  }

  // Faces: sort the neighbours of each vertex counterclockwise, then walk every half-edge with
  // its face on the left (at v, arriving from u, leave along the edge just clockwise of v->u).
  for (int v = 0; v < nv; ++v) {
    const Point2 pv = vertex_point(v);
    std::sort(neighbours[v].begin(), neighbours[v].end(), [&](int a, int b) {
      const Point2 da = vertex_point(a) - pv, db = vertex_point(b) - pv;
      return std::atan2(da.y(), da.x()) < std::atan2(db.y(), db.x());
    });
  }
  std::map<std::pair<int, int>, bool> used;
  for (int u = 0; u < nv; ++u)
    for (int w : neighbours[u]) {
      if (used[{u, w}]) continue;
      std::vector<int> face;
      int a = u, b = w;
      while (!used[{a, b}]) {
        used[{a, b}] = true;
        face.push_back(a);
        const std::vector<int>& nb = neighbours[b];
        const int k = static_cast<int>(std::find(nb.begin(), nb.end(), a) - nb.begin());
        const int next = nb[(k + static_cast<int>(nb.size()) - 1) % nb.size()];
        a = b;
        b = next;
      }
      double area2 = 0.0;
      Point2 c = Point2::Zero();
      for (size_t k = 0; k < face.size(); ++k) {
        area2 += cross2(vertex_point(face[k]), vertex_point(face[(k + 1) % face.size()]));
        c += vertex_point(face[k]);
      }
      if (area2 <= 0.0) continue;  // the outer face
      SplitRegion r;
      r.vertices = face;
      r.area = 0.5 * area2;
      r.centroid = c / static_cast<double>(face.size());  // vertex average: interior for convex polygons
      regions_.push_back(std::move(r));
    }

  for (int r = 0; r < static_cast<int>(regions_.size()); ++r) {
    const std::vector<int>& f = regions_[r].vertices;
    for (size_t k = 1; k + 1 < f.size(); ++k) {
      fan_.push_back({f[0], f[k], f[k + 1]});
      fan_region_.push_back(r);
    }
    const std::uint64_t mask = sign_mask(regions_[r].centroid, kInterior);
    if (!region_of_mask_.emplace(mask, r).second) throw std::logic_error("Ws4Split: two regions share a sign vector");
  }
}

std::uint64_t Ws4Split::sign_mask(const Point2& x, const Point2& toward) const {
  const double lam[3] = {1.0 - x.x() - x.y(), x.x(), x.y()};
  const Point2 d1 = toward - x;
  const double dl1[3] = {-d1.x() - d1.y(), d1.x(), d1.y()};
  const double dl2[3] = {-kSecond.x() - kSecond.y(), kSecond.x(), kSecond.y()};
  std::uint64_t mask = 0;
  for (size_t k = 3; k < lines_.size(); ++k) {
    const Triple& c = lines_[k];
    const double scale = 1e-12 * static_cast<double>(std::llabs(c[0]) + std::llabs(c[1]) + std::llabs(c[2]));
    double s = c[0] * lam[0] + c[1] * lam[1] + c[2] * lam[2];
    if (std::abs(s) <= scale) s = c[0] * dl1[0] + c[1] * dl1[1] + c[2] * dl1[2];
    if (std::abs(s) <= scale) s = c[0] * dl2[0] + c[1] * dl2[1] + c[2] * dl2[2];
    if (s > 0.0) mask |= std::uint64_t{1} << (k - 3);
  }
  return mask;
}

int Ws4Split::locate(const Point2& x) const {
  if (!(x.x() >= -1e-10 && x.y() >= -1e-10 && x.x() + x.y() <= 1.0 + 1e-10))
    throw std::invalid_argument("Ws4Split::locate: point (" + std::to_string(x.x()) + ", " + std::to_string(x.y()) +
                                ") is not in the reference triangle");
  Point2 y = x;
  for (int attempt = 0; attempt < 30; ++attempt) {  // steps up to 5e-4, beyond the 1e-10 slack
    const auto it = region_of_mask_.find(sign_mask(y, kInterior));
    if (it != region_of_mask_.end()) return it->second;
    y += std::ldexp(1e-12, attempt) * (kInterior - x);  // outside by round-off: step inside
  }
  throw std::logic_error("Ws4Split::locate: no region for a point of the triangle");
}

QuadratureRule Ws4Split::composite_rule(int degree) const {
  const QuadratureRule base = triangle_rule(degree);
  std::vector<QuadratureRule> parts;
  parts.reserve(fan_.size());
  for (const auto& t : fan_)
    parts.push_back(map_to_triangle(base, vertex_point(t[0]), vertex_point(t[1]), vertex_point(t[2])));
  return concatenate(parts);
}

}  // namespace iga::ws4
