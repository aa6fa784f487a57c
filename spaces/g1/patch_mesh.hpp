#pragma once
/// @file
/// PatchMesh: a planar multipatch mesh of bilinear quadrilaterals and affine triangles with its
/// topology (shared edges, orientation, vertex fans, boundary) and validation. The geometry of a
/// quad is the bilinear map of its four corners, of a triangle the affine map of its three;
/// refinement splits each face into four with the same map.
///
/// Conventions: a face lists its n = 3 or 4 corners counterclockwise; corner c maps to the
/// reference corner (0,0),(1,0),(1,1),(0,1) (quad) or (0,0),(1,0),(0,1) (triangle); local edge e
/// runs from corner e to corner e+1 (mod n), as in reference_edge_point.

#include <map>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "spaces/push_forward.hpp"

namespace iga {

/// One side of a face: face index and local edge 0..n-1.
struct FaceEdge {
  int face = -1;
  int local_edge = -1;
};

/// A mesh edge. For an interior edge, `first` traverses X -> Y counterclockwise and `second`
/// traverses Y -> X; a boundary edge has only `first` (second.face == -1).
struct MeshEdge {
  int x = -1, y = -1;  ///< end vertices (X, Y) in the direction of `first`
  FaceEdge first, second;
  bool boundary() const { return second.face < 0; }
};

/// The faces around a vertex in counterclockwise order. Face i meets the vertex at corner
/// corner[i]; edge[i] is the edge from the vertex along local edge corner[i] of face i (the
/// "u-axis" τ_i of §1.8 of the notes) and edge[faces] the last edge of a boundary fan. A view into
/// its mesh (valid while the mesh lives).
struct VertexFan {
  std::span<const int> face, corner;
  std::span<const int> edge;  ///< F edges (interior vertex) or F+1 edges (boundary vertex)
  bool boundary = false;
  int valence() const { return static_cast<int>(edge.size()); }
};

/// Named boundary parts as lists of boundary edges, each edge given by its two end vertices.
using BoundaryGroups = std::map<std::string, std::vector<std::pair<int, int>>>;

class PatchMesh {
 public:
  /// Build and validate. `name` is used in messages. Throws InputError for a face with other than
  /// 3 or 4 corners, an inverted, folded or degenerate face (det DG <= 0 at a corner), a repeated
  /// corner, an edge shared by more than two faces (non-manifold), an edge traversed in the same
  /// direction by two faces (inconsistent orientation) and a vertex whose faces do not form one
  /// fan; the message names the patch. `groups` are optional named boundary parts (e.g. Gmsh
  /// physical curves); a group named "all" or with an edge that is not a boundary edge is an
  /// InputError too.
  PatchMesh(std::vector<Point2> vertices, std::vector<std::vector<int>> faces, std::string name,
            BoundaryGroups groups = {});

  /// Each face split into four (edge midpoints, and the centre of the bilinear map for quads); same
  /// geometry. Boundary groups follow (each group edge becomes its two halves).
  PatchMesh refined() const;

  const std::string& name() const { return name_; }
  int num_vertices() const { return static_cast<int>(vertices_.size()); }
  int num_edges() const { return static_cast<int>(edges_.size()); }
  const Point2& vertex(int v) const { return vertices_[v]; }
  /// The corner vertices of face f, counterclockwise.
  std::span<const int> face(int f) const { return {corners_.data() + corner_start_[f], corners_.data() + corner_start_[f + 1]}; }
  int num_faces() const { return static_cast<int>(corner_start_.size()) - 1; }
  int num_corners(int f) const { return corner_start_[f + 1] - corner_start_[f]; }
  CellShape shape(int f) const { return num_corners(f) == 3 ? CellShape::triangle : CellShape::quadrilateral; }
  bool has_triangles() const;
  const MeshEdge& edge(int e) const { return edges_[e]; }
  /// Mesh edge of local edge `local_edge` of face f.
  int face_edge(int f, int local_edge) const { return face_edges_[corner_start_[f] + local_edge]; }
  VertexFan fan(int v) const;
  /// The mesh edge between vertices a and b (either order), or -1.
  int find_edge(int a, int b) const;
  /// Named boundary parts given at construction (empty for most meshes).
  const BoundaryGroups& boundary_groups() const { return groups_; }

  /// Bilinear (quad) or affine (triangle) map of face f at reference point (u,v), with first and
  /// second derivatives.
  GeometryJet map(int f, const Point2& uv) const;
  /// Largest corner-to-corner distance of a face (its diameter: the faces have straight edges).
  double diameter(int f) const;
  /// True when the map of face f is affine (a triangle or a parallelogram).
  bool is_affine(int f) const;

 private:
  void build_topology();
  void build_fans();
  void check_groups() const;

  // Flat arrays, not a vector per face and per vertex: every rank keeps the whole refined mesh (the
  // skeleton of a distributed G1 space): 8.0 MB instead of 14.2 at 49 152 faces (heaptrack).
  std::vector<Point2> vertices_;
  std::vector<int> corner_start_;  ///< face f: corners_[corner_start_[f] .. corner_start_[f + 1])
  std::vector<int> corners_;
  std::string name_;
  std::vector<MeshEdge> edges_;
  std::vector<int> face_edges_;  ///< aligned with corners_: the mesh edge of each local edge
  std::vector<int> fan_start_;   ///< vertex v: fan_faces_, fan_corners_ [fan_start_[v] .. fan_start_[v + 1])
  std::vector<int> fan_faces_, fan_corners_;
  /// vertex v's edges: fan_edges_[fan_edge_start_[v] .. fan_edge_start_[v + 1]), one more than its
  /// faces exactly when its fan is open (a boundary vertex)
  std::vector<int> fan_edge_start_;
  std::vector<int> fan_edges_;
  BoundaryGroups groups_;
};

/// Reference coordinates of corner c (taken mod the number of corners) of the unit square or the
/// unit triangle.
Point2 reference_corner(CellShape shape, int c);

}  // namespace iga
