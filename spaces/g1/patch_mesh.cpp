#include "spaces/g1/patch_mesh.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "config/errors.hpp"

namespace iga {

Point2 reference_corner(CellShape shape, int c) {
  static const Point2 square[4] = {{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}};
  static const Point2 triangle[3] = {{0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}};
  if (shape == CellShape::triangle) return triangle[((c % 3) + 3) % 3];
  return square[((c % 4) + 4) % 4];
}

namespace {

std::string patch_name(const std::string& mesh, int f) {
  return mesh + ": patch " + std::to_string(f);
}

}  // namespace

PatchMesh::PatchMesh(std::vector<Point2> vertices, std::vector<std::vector<int>> faces, std::string name,
                     BoundaryGroups groups)
    : vertices_(std::move(vertices)), name_(std::move(name)), groups_(std::move(groups)) {
  if (faces.empty()) throw InputError(name_ + ": a multipatch mesh needs at least one patch");
  corner_start_.reserve(faces.size() + 1);
  corner_start_.push_back(0);
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const int n = static_cast<int>(faces[f].size());
    if (n != 3 && n != 4)
      throw InputError(patch_name(name_, static_cast<int>(f)) + " has " + std::to_string(n) +
                       " corners (patches are triangles or quadrilaterals)");
    corner_start_.push_back(corner_start_.back() + n);
  }
  corners_.reserve(corner_start_.back());
  for (auto& q : faces) {
    corners_.insert(corners_.end(), q.begin(), q.end());
    std::vector<int>().swap(q);
  }
  for (int f = 0; f < num_faces(); ++f) {
    const auto q = face(f);
    const int n = num_corners(f);
    for (int c = 0; c < n; ++c) {
      if (q[c] < 0 || q[c] >= num_vertices())
        throw InputError(patch_name(name_, f) + " refers to vertex " + std::to_string(q[c]) + " of " +
                         std::to_string(num_vertices()));
      for (int d = 0; d < c; ++d)
        if (q[c] == q[d]) throw InputError(patch_name(name_, f) + " repeats a corner vertex");
    }
    // det DG of a bilinear map is affine in u and in v (constant for a triangle): positive at the
    // corners <=> positive inside.
    const double scale = std::max(diameter(f), 1e-300);
    int positive = 0, negative = 0;
    for (int c = 0; c < n; ++c) {
      const double det = map(f, reference_corner(shape(f), c)).jacobian.determinant();
      if (det > 1e-12 * scale * scale) ++positive;
      else if (det < -1e-12 * scale * scale) ++negative;
    }
    if (negative == n) throw InputError(patch_name(name_, f) + " is inverted (corners listed clockwise)");
    if (positive != n)
      throw InputError(patch_name(name_, f) +
                       (n == 3 ? std::string(" is degenerate (its corners are collinear)")
                               : std::string(" is folded or degenerate (det DG changes sign or vanishes at a corner: "
                                             "not strictly convex)")));
  }
  build_topology();
  build_fans();
  check_groups();
}

int PatchMesh::find_edge(int a, int b) const {
  // Among the edges at a (its fan): no table of all edges kept for this.
  if (a < 0 || a >= num_vertices()) return -1;
  for (int e : fan(a).edge)
    if ((edges_[e].x == a && edges_[e].y == b) || (edges_[e].x == b && edges_[e].y == a)) return e;
  return -1;
}

void PatchMesh::check_groups() const {
  for (const auto& [group, edges] : groups_) {
    if (group == "all")
      throw InputError(name_ + ": boundary group name 'all' is reserved (every boundary edge); rename it");
    for (const auto& [a, b] : edges) {
      const int e = find_edge(a, b);
      if (e < 0 || !edges_[e].boundary())
        throw InputError(name_ + ": boundary group '" + group + "' has the edge between vertices " + std::to_string(a) +
                         " and " + std::to_string(b) + ", which is not a boundary edge");
    }
  }
}

bool PatchMesh::has_triangles() const {
  for (int f = 0; f < num_faces(); ++f)
    if (num_corners(f) == 3) return true;
  return false;
}

VertexFan PatchMesh::fan(int v) const {
  VertexFan fan;
  const int first = fan_start_[v], count = fan_start_[v + 1] - first;
  fan.face = {fan_faces_.data() + first, static_cast<std::size_t>(count)};
  fan.corner = {fan_corners_.data() + first, static_cast<std::size_t>(count)};
  fan.edge = {fan_edges_.data() + fan_edge_start_[v], fan_edges_.data() + fan_edge_start_[v + 1]};
  fan.boundary = fan.edge.size() == fan.face.size() + 1;
  return fan;
}

void PatchMesh::build_topology() {
  // Key: unordered vertex pair. Value: the face sides using it.
  std::map<std::pair<int, int>, std::vector<FaceEdge>> uses;
  for (int f = 0; f < num_faces(); ++f)
    for (int e = 0, n = num_corners(f); e < n; ++e) {
      const int a = face(f)[e], b = face(f)[(e + 1) % n];
      uses[{std::min(a, b), std::max(a, b)}].push_back({f, e});
    }
  face_edges_.assign(corners_.size(), -1);
  for (const auto& [key, list] : uses) {
    if (list.size() > 2) {
      std::ostringstream s;
      s << name_ << ": non-manifold edge between vertices " << key.first << " and " << key.second
        << " is shared by patches";
      for (const FaceEdge& fe : list) s << ' ' << fe.face;
      throw InputError(s.str());
    }
    MeshEdge edge;
    edge.first = list[0];
    edge.x = face(list[0].face)[list[0].local_edge];
    edge.y = face(list[0].face)[(list[0].local_edge + 1) % num_corners(list[0].face)];
    if (list.size() == 2) {
      edge.second = list[1];
      const int x2 = face(list[1].face)[list[1].local_edge];
      if (x2 == edge.x)
        throw InputError(patch_name(name_, list[1].face) + " and patch " + std::to_string(list[0].face) +
                         " traverse their shared edge in the same direction (inconsistent orientation)");
    }
    const int id = num_edges();
    edges_.push_back(edge);
    for (const FaceEdge& fe : list) face_edges_[corner_start_[fe.face] + fe.local_edge] = id;
  }
  edges_.shrink_to_fit();
}

void PatchMesh::build_fans() {
  // Faces at each vertex, then walk counterclockwise: from face i at corner c the next face is the
  // neighbour across local edge c-1 (the edge from the vertex to corner c-1).
  std::vector<int> at_start(num_vertices() + 1, 0);
  for (int q : corners_) ++at_start[q + 1];
  for (int v = 0; v < num_vertices(); ++v) at_start[v + 1] += at_start[v];
  std::vector<std::pair<int, int>> at(corners_.size());  // (face, corner) by vertex
  {
    std::vector<int> next(at_start.begin(), at_start.end() - 1);
    for (int f = 0; f < num_faces(); ++f)
      for (int c = 0; c < num_corners(f); ++c) at[next[face(f)[c]]++] = {f, c};
  }
  auto other_side = [&](int edge_id, int face) -> FaceEdge {
    const MeshEdge& e = edges_[edge_id];
    if (e.boundary()) return {};
    return e.first.face == face ? e.second : e.first;
  };
  fan_start_.assign(1, 0);
  fan_edge_start_.assign(1, 0);
  fan_start_.reserve(num_vertices() + 1);
  fan_edge_start_.reserve(num_vertices() + 1);
  fan_faces_.reserve(corners_.size());
  fan_corners_.reserve(corners_.size());
  fan_edges_.reserve(corners_.size() + num_vertices());
  for (int v = 0; v < num_vertices(); ++v) {
    const std::span<const std::pair<int, int>> faces_at(at.data() + at_start[v], at.data() + at_start[v + 1]);
    if (!faces_at.empty()) {
      // Start at a face whose u-axis edge (local edge c) is a boundary edge, if any: an open fan
      // then ends on the boundary with one edge more than faces (fan() reads that as `boundary`).
      std::pair<int, int> start = faces_at[0];
      for (const auto& [f, c] : faces_at)
        if (edges_[face_edge(f, c)].boundary()) start = {f, c};
      auto [f, c] = start;
      std::size_t count = 0;
      for (size_t step = 0; step <= faces_at.size(); ++step) {
        fan_faces_.push_back(f);
        fan_corners_.push_back(c);
        fan_edges_.push_back(face_edge(f, c));
        ++count;
        const int next_edge = face_edge(f, (c + num_corners(f) - 1) % num_corners(f));
        const FaceEdge n = other_side(next_edge, f);
        if (n.face < 0) {
          fan_edges_.push_back(next_edge);
          break;
        }
        // In the neighbour the shared edge runs from corner(c-1) to the vertex, i.e. it starts at v.
        f = n.face;
        c = n.local_edge;
        if (f == start.first && c == start.second) break;
      }
      if (count != faces_at.size())
        throw InputError(name_ + ": the patches at vertex " + std::to_string(v) +
                         " do not form a single fan (non-manifold vertex), e.g. patch " +
                         std::to_string(faces_at[0].first));
    }
    fan_start_.push_back(static_cast<int>(fan_faces_.size()));
    fan_edge_start_.push_back(static_cast<int>(fan_edges_.size()));
  }
}

GeometryJet PatchMesh::map(int f, const Point2& uv) const {
  const auto q = face(f);
  const double u = uv.x(), v = uv.y();
  GeometryJet g;
  if (q.size() == 3) {
    const Point2 &p0 = vertices_[q[0]], &p1 = vertices_[q[1]], &p2 = vertices_[q[2]];
    g.x = p0 + u * (p1 - p0) + v * (p2 - p0);
    g.jacobian.col(0) = p1 - p0;
    g.jacobian.col(1) = p2 - p0;
    g.hessian_x.setZero();
    g.hessian_y.setZero();
    return g;
  }
  const Point2 &p0 = vertices_[q[0]], &p1 = vertices_[q[1]], &p2 = vertices_[q[2]], &p3 = vertices_[q[3]];
  g.x = (1 - u) * (1 - v) * p0 + u * (1 - v) * p1 + u * v * p2 + (1 - u) * v * p3;
  g.jacobian.col(0) = (1 - v) * (p1 - p0) + v * (p2 - p3);
  g.jacobian.col(1) = (1 - u) * (p3 - p0) + u * (p2 - p1);
  const Point2 twist = p0 - p1 + p2 - p3;  // d^2 G / du dv; the pure second derivatives vanish
  g.hessian_x << 0.0, twist.x(), twist.x(), 0.0;
  g.hessian_y << 0.0, twist.y(), twist.y(), 0.0;
  return g;
}

double PatchMesh::diameter(int f) const {
  double h = 0.0;
  const int n = num_corners(f);
  for (int a = 0; a < n; ++a)
    for (int b = a + 1; b < n; ++b) h = std::max(h, (vertices_[face(f)[a]] - vertices_[face(f)[b]]).norm());
  return h;
}

bool PatchMesh::is_affine(int f) const {
  const auto q = face(f);
  if (q.size() == 3) return true;
  const Point2 twist = vertices_[q[0]] - vertices_[q[1]] + vertices_[q[2]] - vertices_[q[3]];
  return twist.norm() <= 1e-14 * diameter(f);
}

PatchMesh PatchMesh::refined() const {
  std::vector<Point2> v = vertices_;
  std::vector<int> mid(num_edges(), -1);
  for (int e = 0; e < num_edges(); ++e) {
    mid[e] = static_cast<int>(v.size());
    v.push_back(0.5 * (vertices_[edges_[e].x] + vertices_[edges_[e].y]));
  }
  std::vector<std::vector<int>> faces;
  faces.reserve(4 * num_faces());
  for (int f = 0; f < num_faces(); ++f) {
    const auto q = face(f);
    const int n = num_corners(f);
    std::vector<int> m(n);
    for (int e = 0; e < n; ++e) m[e] = mid[face_edge(f, e)];
    if (n == 3) {
      // Corner children keep corner c; the middle triangle is the medial one (counterclockwise:
      // it is the parent turned by 180 degrees).
      for (int c = 0; c < 3; ++c) faces.push_back({q[c], m[c], m[(c + 2) % 3]});
      faces.push_back({m[0], m[1], m[2]});
      continue;
    }
    const int centre = static_cast<int>(v.size());
    v.push_back(map(f, Point2(0.5, 0.5)).x);
    // Child c keeps corner c: (corner c, mid of edge c, centre, mid of edge c-1), counterclockwise.
    for (int c = 0; c < 4; ++c) faces.push_back({q[c], m[c], centre, m[(c + 3) % 4]});
  }
  BoundaryGroups groups;
  for (const auto& [group, edges] : groups_)
    for (const auto& [a, b] : edges) {
      const int m = mid[find_edge(a, b)];
      groups[group].push_back({a, m});
      groups[group].push_back({m, b});
    }
  return PatchMesh(std::move(v), std::move(faces), name_, std::move(groups));
}

}  // namespace iga
