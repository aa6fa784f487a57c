#pragma once
/// @file
/// The combinatorics the 4-split G1 space is built on: quad faces given by 4 vertex ids (corner c at
/// (0,0),(1,0),(1,1),(0,1) of the face's unit square, local edge j from corner j to corner j+1),
/// the edges with their one (boundary) or two (interior) face sides, and per vertex the number of
/// faces and whether it lies on the boundary. Planar meshes and closed surfaces alike; the faces need
/// not be consistently oriented.

#include <array>
#include <string>
#include <vector>

namespace iga {

/// One side of an edge: face and local edge 0..3.
struct QuadSide {
  int face = -1;
  int local_edge = -1;
};

struct QuadEdge {
  int g0 = -1, g1 = -1;          ///< end vertices, g0 < g1; the edge parameter t runs g0 -> g1
  std::vector<QuadSide> sides;   ///< 1 (boundary) or 2 (interior)
  bool boundary() const { return sides.size() == 1; }
};

class QuadTopology {
 public:
  /// Throws InputError (message starts with `name`) for a face with a repeated corner or an edge
  /// shared by more than two faces.
  QuadTopology(int num_vertices, std::vector<std::array<int, 4>> faces, std::string name);

  /// Each face split into 4: child 4f + c keeps corner c of face f and is (corner c, mid of edge c,
  /// centre, mid of edge c-1), as PatchMesh::refined numbers its faces. Child local edge 0 is the
  /// first half of parent edge c, child local edge 3 the second half of parent edge c-1, child local
  /// edges 1 and 2 lie inside the parent.
  QuadTopology refined() const;

  const std::string& name() const { return name_; }
  int num_vertices() const { return num_vertices_; }
  int num_faces() const { return static_cast<int>(faces_.size()); }
  int num_edges() const { return static_cast<int>(edges_.size()); }
  const std::array<int, 4>& face(int f) const { return faces_[f]; }
  const QuadEdge& edge(int e) const { return edges_[e]; }
  int face_edge(int f, int j) const { return face_edges_[f][j]; }
  /// Number of faces at vertex v.
  int vertex_faces(int v) const { return static_cast<int>(vertex_corners_[v].size()); }
  bool vertex_on_boundary(int v) const { return vertex_boundary_[v]; }
  /// (face, corner) pairs of the faces at vertex v.
  const std::vector<std::pair<int, int>>& vertex_corners(int v) const { return vertex_corners_[v]; }
  /// Edges at vertex v.
  const std::vector<int>& vertex_edges(int v) const { return vertex_edges_[v]; }

 private:
  int num_vertices_;
  std::vector<std::array<int, 4>> faces_;
  std::string name_;
  std::vector<QuadEdge> edges_;
  std::vector<std::array<int, 4>> face_edges_;
  std::vector<bool> vertex_boundary_;
  std::vector<std::vector<std::pair<int, int>>> vertex_corners_;
  std::vector<std::vector<int>> vertex_edges_;
};

/// Closed quad surfaces (topology only): the cube (8 vertices of valence 3, 6 faces) and the
/// Catmull–Clark split tetrahedron (4 + 6 + 4 vertices, 12 faces).
QuadTopology cube_topology();
QuadTopology split_tetrahedron_topology();

}  // namespace iga
