#include "spaces/g1_4split/g1_4split_meshes.hpp"

#include <cmath>
#include <stdexcept>

#include "config/errors.hpp"
#include "spaces/g1/multipatch_domains.hpp"

namespace iga {

std::vector<std::string> g14_domain_names() {
  return {"fan3", "fan5", "fan6", "grid2x2", "halffan3", "fan3+", "fan5+", "fan3s", "fan5s", "fan6s"};
}

PatchMesh g14_domain(const std::string& name) {
  const double pi = std::acos(-1.0);
  using P = Point2;
  if (name == "fan3s" || name == "fan5s" || name == "fan6s") {
    // The fan split once before use: its spoke midpoints are interior crossing vertices next to
    // the centre, the meshes on which per-edge linear gluing data break the twist condition.
    const PatchMesh split = g14_domain(name.substr(0, 4)).refined();
    std::vector<Point2> vertices;
    for (int v = 0; v < split.num_vertices(); ++v) vertices.push_back(split.vertex(v));
    std::vector<std::vector<int>> faces;
    for (int f = 0; f < split.num_faces(); ++f) faces.emplace_back(split.face(f).begin(), split.face(f).end());
    return PatchMesh(std::move(vertices), std::move(faces), name);
  }
  if (name == "fan3" || name == "fan5" || name == "fan6" || name == "fan3+" || name == "fan5+") {
    const int n = name[3] - '0';
    const bool plus = name.size() == 5;
    std::vector<P> s(n), c(n);
    for (int i = 0; i < n; ++i) {
      s[i] = std::cos(pi / n) * P(std::cos(2 * pi * i / n), std::sin(2 * pi * i / n));
      c[i] = P(std::cos((2 * i - 1) * pi / n), std::sin((2 * i - 1) * pi / n));
    }
    // The extra quad [s0, c0, p, c1] makes s0 an interior valence-3 vertex; s0 moves in along its
    // spoke so that its three edges are not in a half-plane (an affine image of a regular 3-fan).
    if (plus) s[0] *= 0.6;
    std::vector<PatchCorners> patches;
    for (int i = 0; i < n; ++i) patches.push_back({P(0, 0), s[(i + n - 1) % n], c[i], s[i]});
    if (plus) patches.push_back({s[0], c[0], P(1.6 * std::cos(pi / n) + 0.4, 0), c[1 % n]});
    return mesh_from_patches(patches, name);
  }
  if (name == "grid2x2") {
    std::vector<PatchCorners> patches;
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i)
        patches.push_back({P(0.5 * i, 0.5 * j), P(0.5 * (i + 1), 0.5 * j), P(0.5 * (i + 1), 0.5 * (j + 1)),
                           P(0.5 * i, 0.5 * (j + 1))});
    return mesh_from_patches(patches, name);
  }
  if (name == "halffan3") {
    const double r = std::cos(pi / 6);
    std::vector<P> s(4), c(3);
    for (int j = 0; j < 4; ++j) s[j] = r * P(std::cos(j * pi / 3), std::sin(j * pi / 3));
    for (int i = 0; i < 3; ++i) c[i] = P(std::cos((2 * i + 1) * pi / 6), std::sin((2 * i + 1) * pi / 6));
    std::vector<PatchCorners> patches;
    for (int i = 0; i < 3; ++i) patches.push_back({P(0, 0), s[i], c[i], s[i + 1]});
    return mesh_from_patches(patches, name);
  }
  throw std::invalid_argument("unknown g1_4split domain '" + name + "'");
}

QuadTopology quad_topology(const PatchMesh& mesh) {
  std::vector<std::array<int, 4>> faces;
  for (int f = 0; f < mesh.num_faces(); ++f) {
    const auto& q = mesh.face(f);
    if (q.size() != 4)
      throw InputError(mesh.name() + ": patch " + std::to_string(f) +
                       " is a triangle; the g1_4split space needs a quad mesh (use the g1 space for meshes with "
                       "triangles)");
    faces.push_back({q[0], q[1], q[2], q[3]});
  }
  return QuadTopology(mesh.num_vertices(), std::move(faces), mesh.name());
}

std::vector<double> vertex_angles(const PatchMesh& mesh) {
  std::vector<double> angle(mesh.num_vertices(), 0.0);
  for (int f = 0; f < mesh.num_faces(); ++f) {
    const auto& q = mesh.face(f);
    const int n = static_cast<int>(q.size());
    for (int c = 0; c < n; ++c) {
      const Point2 a = mesh.vertex(q[(c + 1) % n]) - mesh.vertex(q[c]);
      const Point2 b = mesh.vertex(q[(c + n - 1) % n]) - mesh.vertex(q[c]);
      angle[q[c]] += std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
    }
  }
  return angle;
}

QuadTopology fan_topology(int n, bool plus) {
  std::vector<std::array<int, 4>> faces;
  auto s = [&](int i) { return 1 + (i + n) % n; };
  auto c = [&](int i) { return n + 1 + i; };
  for (int i = 0; i < n; ++i) faces.push_back({0, s(i - 1), c(i), s(i)});
  if (plus) faces.push_back({s(0), c(0), 2 * n + 1, c(1)});
  return QuadTopology(2 * n + 1 + (plus ? 1 : 0), std::move(faces), "fan" + std::to_string(n) + (plus ? "+" : ""));
}

}  // namespace iga
