#include "spaces/g1/multipatch_domains.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace iga {

namespace {

double shoelace(const PatchCorners& p) {
  double a = 0.0;
  const size_t n = p.size();
  for (size_t i = 0; i < n; ++i) a += p[i].x() * p[(i + 1) % n].y() - p[(i + 1) % n].x() * p[i].y();
  return a;
}

/// Tensor-order control points (0,0),(1,0),(0,1),(1,1) to cyclic order.
PatchCorners tensor(Point2 p00, Point2 p10, Point2 p01, Point2 p11) { return {p00, p10, p11, p01}; }

}  // namespace

PatchMesh mesh_from_patches(const std::vector<PatchCorners>& patches, const std::string& name) {
  double size = 0.0;
  for (const auto& p : patches)
    for (const Point2& x : p) size = std::max(size, x.cwiseAbs().maxCoeff());
  const double tol = 1e-12 * std::max(size, 1.0);
  std::vector<Point2> vertices;
  std::vector<std::vector<int>> faces;
  for (auto p : patches) {
    if (shoelace(p) < 0.0) std::reverse(p.begin() + 1, p.end());
    std::vector<int> f(p.size());
    for (size_t c = 0; c < p.size(); ++c) {
      int found = -1;
      for (int v = 0; v < static_cast<int>(vertices.size()) && found < 0; ++v)
        if ((vertices[v] - p[c]).cwiseAbs().maxCoeff() <= tol) found = v;
      if (found < 0) {
        found = static_cast<int>(vertices.size());
        vertices.push_back(p[c]);
      }
      f[c] = found;
    }
    faces.push_back(f);
  }
  return PatchMesh(std::move(vertices), std::move(faces), name);
}

std::vector<std::string> multipatch_domain_names() {
  return {"3p_square", "5p_square",     "pentagon", "5p_pentagon", "3p_hexagon", "lshape_8p",
          "4t_crisscross", "4t_star", "2q2t_square"};
}

PatchMesh multipatch_domain(const std::string& name) {
  using P = Point2;
  if (name == "3p_square")
    return mesh_from_patches({tensor(P(0, 0), P(0.4, 0), P(0, 1), P(0.6, 0.6)),
                              tensor(P(0.6, 0.6), P(1, 0.7), P(0, 1), P(1, 1)),
                              tensor(P(0.4, 0), P(1, 0), P(0.6, 0.6), P(1, 0.7))},
                             name);
  if (name == "5p_square")
    return mesh_from_patches({tensor(P(1, 0), P(1, 1), P(0.8, 0.2), P(0.8, 0.8)),
                              tensor(P(1, 1), P(0, 1), P(0.8, 0.8), P(0.2, 0.8)),
                              tensor(P(0, 1), P(0, 0), P(0.2, 0.8), P(0.2, 0.2)),
                              tensor(P(0, 0), P(1, 0), P(0.2, 0.2), P(0.8, 0.2)),
                              tensor(P(0.2, 0.8), P(0.8, 0.8), P(0.2, 0.2), P(0.8, 0.2))},
                             name);
  if (name == "pentagon") {
    const double pi = std::acos(-1.0);
    P v[5], m[5];
    for (int i = 0; i < 5; ++i) {
      const double th = pi / 2 + 2 * pi * i / 5;
      v[i] = P(std::cos(th), std::sin(th));
    }
    for (int i = 0; i < 5; ++i) m[i] = 0.5 * (v[i] + v[(i + 1) % 5]);
    const P o(0.07, -0.04);
    std::vector<PatchCorners> patches;
    for (int i = 0; i < 5; ++i) patches.push_back({o, m[(i + 4) % 5], v[i], m[i]});
    return mesh_from_patches(patches, name);
  }
  if (name == "5p_pentagon") {
    const double a = 0.6881909602355869, b = 0.654508497187474, c = 0.21266270208801, d = 0.809016994374947,
                 e = 0.262865556059567, f = 0.404508497187474, g = 0.556758182205803, h = 0.85065080835204;
    return mesh_from_patches({tensor(P(-0.5, -a), P(0, -a), P(-b, -c), P(0, 0)),
                              tensor(P(0, -a), P(0.5, -a), P(0, 0), P(b, -c)),
                              tensor(P(-b, -c), P(0, 0), P(-d, e), P(-f, g)),
                              tensor(P(b, -c), P(0, 0), P(d, e), P(f, g)),
                              tensor(P(0, 0), P(f, g), P(-f, g), P(0, h))},
                             name);
  }
  if (name == "3p_hexagon") {
    const double s = 0.8660254037844386;
    return mesh_from_patches({tensor(P(0, 0), P(s, -0.5), P(0, 1), P(s, 0.5)),
                              tensor(P(-s, -0.5), P(0, 0), P(-s, 0.5), P(0, 1)),
                              tensor(P(0, -1), P(s, -0.5), P(-s, -0.5), P(0, 0))},
                             name);
  }
  if (name == "lshape_8p") {
    const double t = 1.0 / 3, u = 2.0 / 3;
    return mesh_from_patches({tensor(P(0, 0), P(1, 0), P(-t, t), P(u, t)),
                              tensor(P(0, 0), P(0, -1), P(-t, t), P(-t, -u)),
                              tensor(P(-t, -u), P(0, -1), P(-u, -u), P(-1, -1)),
                              tensor(P(-1, -1), P(-1, 1), P(-u, -u), P(-u, u)),
                              tensor(P(-u, -u), P(-u, u), P(-t, -u), P(-t, t)),
                              tensor(P(-u, u), P(u, u), P(-t, t), P(u, t)),
                              tensor(P(-1, 1), P(1, 1), P(-u, u), P(u, u)),
                              tensor(P(u, t), P(u, u), P(1, 0), P(1, 1))},
                             name);
  }
  if (name == "4t_crisscross" || name == "4t_star") {
    const P c = name == "4t_crisscross" ? P(0.5, 0.5) : P(0.45, 0.6);
    return mesh_from_patches({{P(0, 0), P(1, 0), c}, {P(1, 0), P(1, 1), c}, {P(1, 1), P(0, 1), c}, {P(0, 1), P(0, 0), c}},
                             name);
  }
  if (name == "2q2t_square") {
    const P e(0.55, 0.45), right(1, 0.5), left(0, 0.5);
    return mesh_from_patches({{P(0, 0), P(1, 0), right, e}, {right, P(1, 1), e}, {P(1, 1), P(0, 1), left, e}, {left, P(0, 0), e}},
                             name);
  }
  throw std::invalid_argument("unknown multipatch domain '" + name + "'");
}

}  // namespace iga
