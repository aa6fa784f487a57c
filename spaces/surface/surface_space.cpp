#include "spaces/surface/surface_space.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>

#include "geometry/rsd/bezier_jet.hpp"
#include "spaces/g1/bernstein_face.hpp"
#include "spaces/extracted_evaluator.hpp"

namespace iga {

namespace {

using Key = std::array<int, 4>;

/// The global identity of lattice point k (integer barycentrics, sum N) of triangle `tri`:
/// a mesh vertex, a position on a mesh edge counted from its smaller vertex, or a patch interior point.
Key lattice_key(const std::array<int, 3>& tri, int patch, const std::array<int, 3>& k) {
  int nonzero = 0;
  for (int a = 0; a < 3; ++a) nonzero += k[a] != 0;
  if (nonzero == 1) {
    for (int a = 0; a < 3; ++a)
      if (k[a] != 0) return {0, tri[a], 0, 0};
  }
  if (nonzero == 2) {
    int a = 0;
    while (k[a] == 0) ++a;
    int b = a + 1;
    while (k[b] == 0) ++b;
    if (tri[a] > tri[b]) std::swap(a, b);
    return {1, tri[a], tri[b], k[a]};
  }
  return {2, patch, k[0], k[1]};
}

}  // namespace

SurfaceBernsteinSpace::SurfaceBernsteinSpace(std::shared_ptr<const rsd::RsdSurface> surface, int degree,
                                             int subdivisions, std::shared_ptr<const SurfacePatches> patches)
    : surface_(std::move(surface)), degree_(degree) {
  SpaceFacts facts;
  // The surface's own report (made here unless another space already made it).
  facts.surface_patches = patches ? std::move(patches) : std::make_shared<const SurfacePatches>(surface_patches_of(*surface_));
  if (degree < 1 || degree > 8) throw std::invalid_argument("SurfaceBernsteinSpace: degree must be in 1..8");
  if (subdivisions < 1) throw std::invalid_argument("SurfaceBernsteinSpace: subdivisions must be >= 1");
  const int m = subdivisions, p = degree;
  const TriangleSurfaceMesh& mesh = surface_->mesh;
  std::map<std::pair<int, int>, int> edge_count;
  for (const auto& t : mesh.triangles)
    for (int a = 0; a < 3; ++a) ++edge_count[std::minmax(t[a], t[(a + 1) % 3])];

  std::map<Key, int> numbering;
  // Element edges by their end points (global lattice keys of the m-lattice): the first element
  // seen and the key its edge starts at; the second one closes an interior edge.
  std::map<std::pair<Key, Key>, std::pair<BoundaryEdge, Key>> open_edges;
  for (int n = 0; n < mesh.num_triangles(); ++n) {
    const auto& tri = mesh.triangles[n];
    // Lattice point (i, j) of the patch reference coordinates (ξ, η) = (i/m, j/m) has barycentrics
    // (m − i − j, i, j): both kinds of sub-triangle are counterclockwise in (ξ, η).
    std::vector<std::array<std::array<int, 3>, 3>> subs;
    const auto bary = [m](int i, int j) { return std::array<int, 3>{m - i - j, i, j}; };
    for (int j = 0; j < m; ++j)
      for (int i = 0; i + j < m; ++i) {
        subs.push_back({bary(i, j), bary(i + 1, j), bary(i, j + 1)});
        if (i + j + 2 <= m) subs.push_back({bary(i + 1, j), bary(i + 1, j + 1), bary(i, j + 1)});
      }
    for (const auto& s : subs) {
      Element el;
      el.patch = n;
      for (int c = 0; c < 3; ++c) el.corner[c] = Eigen::Vector3d(s[c][0], s[c][1], s[c][2]) / m;
      std::vector<int> dofs(bezier_count(p));
      for (int b1 = p; b1 >= 0; --b1)
        for (int b2 = p - b1; b2 >= 0; --b2) {
          const int b3 = p - b1 - b2;
          std::array<int, 3> k;
          for (int a = 0; a < 3; ++a) k[a] = b1 * s[0][a] + b2 * s[1][a] + b3 * s[2][a];
          const auto [it, inserted] = numbering.try_emplace(lattice_key(tri, n, k), facts.dimension);
          if (inserted) ++facts.dimension;
          dofs[bernstein_triangle_index(p, b2, b3)] = it->second;
        }
      // Edges of the reference triangle: 0 = corners (0,1), 1 = (1,2), 2 = (2,0), each running from
      // its first corner to its second (reference_edge_point).
      for (int edge = 0; edge < 3; ++edge) {
        const Key from = lattice_key(tri, n, s[edge]), to = lattice_key(tri, n, s[(edge + 1) % 3]);
        const auto key = std::minmax(from, to);
        const BoundaryEdge here{static_cast<int>(elements_.size()), edge};
        const auto it = open_edges.find(key);
        if (it == open_edges.end()) {
          open_edges.emplace(key, std::make_pair(here, from));
          continue;
        }
        const auto& [first, first_from] = it->second;
        // The same parameter t on both sides when both edges start at the same point.
        const bool reversed = first_from != from;
        interior_.push_back({first.element, first.local_edge, 0.0, 1.0, here.element, here.local_edge,
                             reversed ? 1.0 : 0.0, reversed ? 0.0 : 1.0});
        open_edges.erase(it);
      }
      // An element edge lies on a mesh edge when both corners have the same zero barycentric.
      for (int edge = 0; edge < 3; ++edge) {
        const auto& u = s[edge];
        const auto& v = s[(edge + 1) % 3];
        for (int a = 0; a < 3; ++a)
          if (u[a] == 0 && v[a] == 0 && edge_count[std::minmax(tri[(a + 1) % 3], tri[(a + 2) % 3])] == 1)
            facts.all_boundary_edges.push_back({static_cast<int>(elements_.size()), edge});
      }
      const BezierTriangle& patch = surface_->patches[n];
      for (int c = 0; c < 3; ++c)
        facts.mesh_size = std::max(facts.mesh_size, (patch.value(el.corner[c]) - patch.value(el.corner[(c + 1) % 3])).norm());
      elements_.push_back(el);
      dofs_.push_back(std::move(dofs));
    }
  }
  facts.type = "surface";
  facts.parameters = {{"degree", std::to_string(degree_)},
                      {"subdivisions", std::to_string(subdivisions)},
                      {"elements", std::to_string(elements_.size())},
                      {"surface_triangles", std::to_string(surface_->mesh.num_triangles())}};
  facts.num_elements = static_cast<int>(elements_.size());
  facts.cell_shapes = {CellShape::triangle};
  facts.degree = degree_;
  facts.ambient_dimension = 3;
  set_facts(std::move(facts));
}

/// The explicit core (element_core.hpp): degree-p Bernstein on the reference triangle (the G1
/// faces' local basis, bernstein_face.hpp: λ = (1 − ξ − η, ξ, η)), the
/// identity extraction (the active functions are the Bernstein polynomials, numbered through the
/// patch lattice) and the patch map composed with the sub-triangle's affine map.
struct SurfaceBernsteinSpace::Core {
  using Jet = SurfaceJet;
  static constexpr bool identity = true;
  const SurfaceBernsteinSpace& space;

  int kind(int /*e*/) const { return 0; }
  int tabulate(int /*kind*/, const std::vector<Point2>& points, int /*order*/, LocalTables& t) const {
    bernstein_tables(CellShape::triangle, space.degree_, points, t);
    return 2;
  }
  const std::vector<int>& active(int e) const { return space.dofs_[e]; }
  void map(int e, const QuadratureRule& rule, const LocalTables& /*t*/, int order, std::vector<Jet>& jets) const {
    const Element& el = space.elements_[e];
    const BezierTriangle& patch = space.surface_->patches[el.patch];
    // t = c0 + ξ (c1 − c0) + η (c2 − c0) in patch barycentrics: x_ξ = Σ_a ∂_aF u_a and
    // x_ξη = Σ_ab ∂_abF u_a v_b with u = c1 − c0, v = c2 − c0.
    const Eigen::Vector3d dir[2] = {el.corner[1] - el.corner[0], el.corner[2] - el.corner[0]};
    const bool second = order >= 2;
    jets.resize(rule.size());
    for (int k = 0; k < rule.size(); ++k) {
      const Point2& r = rule.points[k];
      const BezierJet jet = bezier_jet(patch, el.corner[0] + r.x() * dir[0] + r.y() * dir[1], second);
      Eigen::Matrix<double, 3, 2> J;
      for (int c = 0; c < 2; ++c) J.col(c) = jet.d[0] * dir[c](0) + jet.d[1] * dir[c](1) + jet.d[2] * dir[c](2);
      if (!second) {
        fill_surface_jet(jets[k], jet.x, J);
        continue;
      }
      const auto along = [&](const Eigen::Vector3d& u, const Eigen::Vector3d& v) {
        Eigen::Vector3d s = Eigen::Vector3d::Zero();
        for (int a = 0; a < 3; ++a)
          for (int b = 0; b < 3; ++b) s += u(a) * v(b) * jet.dd[a][b];
        return s;
      };
      const std::array<Eigen::Vector3d, 3> dd = {along(dir[0], dir[0]), along(dir[0], dir[1]), along(dir[1], dir[1])};
      fill_surface_jet(jets[k], jet.x, J, &dd);
    }
  }
};

std::unique_ptr<Space::Evaluator> SurfaceBernsteinSpace::make_evaluator() const {
  return std::make_unique<ExtractedEvaluator<Core>>(*this, Core{*this});
}

}  // namespace iga
