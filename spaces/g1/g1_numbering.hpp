#pragma once
/// @file
/// The G1 basis of g1_basis.hpp without holding it whole: its numbering from per-entity counts
/// (what a rank's skeleton keeps, a few ints per edge, vertex and face) and the basis on some faces
/// only (what a rank's part keeps). build_g1_basis numbers the functions edge by edge, then vertex
/// by vertex, then face by face, each entity's in the order its local problem gives them; so do
/// these, and every function has the same number and the same coefficients, bit for bit.

#include <vector>

#include "spaces/g1/g1_basis.hpp"

namespace iga {

struct G1Numbering {
  int degree = 0;
  /// Functions of edge e are edge_first[e] .. edge_first[e+1] − 1; likewise vertices and faces.
  /// edge_first.back() == vertex_first.front(), vertex_first.back() == face_first.front().
  std::vector<int> edge_first, vertex_first, face_first;
  /// (face, function): a function of an edge or vertex of the face whose coefficients on that face
  /// all come out exactly zero, so that the face is not in its support (sorted; rarely any).
  std::vector<std::pair<int, int>> not_on_face;
  int dimension() const { return face_first.empty() ? 0 : face_first.back(); }
  /// The functions active on face f, increasing: those of its edges, its corners and its interior
  /// (build_g1_basis's face_dofs[f]).
  void face_dofs(const PatchMesh& mesh, int f, std::vector<int>& out) const;
};

/// The numbering of build_g1_basis(mesh, gluing, k). Solves every local problem to count its
/// functions, one vertex fan at a time (memory of the largest fan's problems, not of the mesh), and
/// throws the IncompleteBasis build_g1_basis throws, with the same message.
G1Numbering number_g1_basis(const PatchMesh& mesh, const std::vector<EdgeGluing>& gluing, int k);

/// The basis on `faces` (increasing) only: face_dofs and extraction have one entry per face of
/// `faces`, in that order (equal to build_g1_basis's entries of those faces); `info` stays empty.
/// Solves the local problems of the faces' edges and corners (and the edges at those corners).
G1Basis build_g1_basis_on(const PatchMesh& mesh, const std::vector<EdgeGluing>& gluing, const G1Numbering& numbering,
                          const std::vector<int>& faces);

}  // namespace iga
