#pragma once
/// @file
/// G14Space: the C1 space of G1 splines from 4-split macro-patches (Blidia–Mourrain–Villamizar) on
/// a planar quad mesh, isoparametric: each face carries a tensor B-spline of bidegree (k, k) with the
/// interior knot 1/2 (class C^r there), glued with the symmetric data, and the physical map lies in
/// the same space. Elements are the mesh faces; their polynomial pieces are the 4 sub-squares.

#include <memory>

#include "spaces/g1/patch_mesh.hpp"
#include "spaces/g1_4split/g1_4split_basis.hpp"
#include "spaces/g1_4split/g1_4split_geometry.hpp"
#include "spaces/g1_4split/nested_geometry.hpp"
#include "spaces/gauss_rule_cache.hpp"
#include "spaces/builds_on_elements.hpp"
#include "spaces/space.hpp"

namespace iga {

/// How the level-0 map is fitted into the space: `fair` (fair_geometry.hpp: boundary on the mesh's
/// segments, smoothest correction of the bilinear map) or `least_squares` (project_geometry).
enum class GeometryFit { fair, least_squares };

/// What to build: degree, regularity, blending, levels of uniform refinement and whether the
/// refined spaces inherit the coarse gluing and geometry (nested) or rebuild both per level.
struct G14Options {
  int degree = 5;
  int regularity = 1;
  Blending blending = Blending::lines;
  int level = 0;
  bool nested = true;
  GeometryFit fit = GeometryFit::fair;
  /// false (the default fit): a fair map that is not certified regular gives way to the
  /// least-squares map; true (asked for): it is refused (InputError).
  bool fit_required = false;
  /// skeleton: the functions counted per vertex and edge, no local problem kept (BuildsOnElements);
  /// build_on solves those of the entities at its faces.
  SpaceExtent extent = SpaceExtent::whole;
};

/// Every interior edge of `t` once, with the faces' parameters (t runs the same or opposite way).
std::vector<InteriorEdge> quad_interior_edges(const QuadTopology& t);

class G14Space final : public Space, public BuildsOnElements {
 public:
  /// Build on `coarse` refined `options.level` times. Throws NotSeparable when the degree is below
  /// the separability degree of some edge, InputError when the geometry is not regular.
  G14Space(const PatchMesh& coarse, const G14Options& options);

  /// Facts: type "g1_4split", C1, curved elements (the map is in the space), boundary parts of
  /// the level mesh (boundary_parts.hpp).
  std::unique_ptr<Evaluator> make_evaluator() const override;
  /// The functions of the face's vertices, edges and its own (G14Numbering::face_functions).
  void element_dofs(int element, std::vector<int>& out) const override;

  RulePtr quadrature(int, int degree) const override { return rules_.cell(degree); }
  RulePtr edge_quadrature(int, int edge, int degree) const override { return rules_.edge(edge, degree); }

  /// Every interior edge once; the g1_jump check samples 4k + 8 points of each (the jump is
  /// piecewise rational of moderate degree on each half).
  std::vector<InteriorEdge> interior_edges() const override { return quad_interior_edges(*topology_); }

  /// The space with the extractions of `elements` (increasing) only, sharing topology, gluing,
  /// geometry and numbering: it solves the local problems of the vertices and edges at those faces
  /// only (the same problems as the whole basis, so the same extractions bit for bit). Its basis
  /// has no `functions` matrix and no face_dofs; `extraction` holds the built faces' only.
  SpacePtr build_on(const std::vector<int>& elements) const override;
  bool built_on(int element) const override { return slot_[element] >= 0; }

  const QuadTopology& topology() const { return *topology_; }
  /// Face `element`'s extraction, (m+1)² x its functions; std::logic_error when not built on.
  const Eigen::SparseMatrix<double>& extraction(int element) const;
  const G14Basis& basis() const { return basis_; }
  /// Every face's map (a whole space; a space built on some elements shares its skeleton's). A
  /// skeleton of a nested level keeps the level-0 map only: empty (face_geometry).
  const FaceGeometry& geometry() const { return skeleton_ ? skeleton_->geometry_ : geometry_; }
  /// Face f's map, whatever the space keeps: every face's, the built faces' (by slot), or
  /// subdivided from the level-0 map along `path` (then x, y point into `path`).
  void face_geometry(int f, NestedGeometry::Path& path, const Eigen::VectorXd*& x, const Eigen::VectorXd*& y) const;
  const std::vector<SplitGluing>& gluing() const { return skeleton_ ? skeleton_->gluing_ : gluing_; }
  /// (A space built on some elements holds the skeleton itself, never another built space.)

 private:
  G14Options options_;
  /// A skeleton's space built on `elements` (increasing).
  G14Space(std::shared_ptr<const G14Space> skeleton, const std::vector<int>& elements);

  std::shared_ptr<const QuadTopology> topology_;
  std::vector<SplitGluing> gluing_;  ///< empty in a space built on some elements: its skeleton's
  /// Whole: everything. Skeleton: bspline and numbering. Built on some faces: and their
  /// extractions, in the order of the faces.
  G14Basis basis_;
  /// Whole: every face's map. Skeleton of a nested level: empty (nested_). Built on some faces:
  /// empty (its skeleton's), or, when the skeleton has nested_, the built faces' (by slot).
  FaceGeometry geometry_;
  std::shared_ptr<const NestedGeometry> nested_;  ///< a skeleton's level-0 map of a nested level
  std::shared_ptr<const G14Space> skeleton_;  ///< the skeleton of a space built on some elements
  /// Per face: its extraction's index in basis_.extraction, or -1 (not built on).
  std::vector<int> slot_;
  GaussRuleCache rules_{2};  ///< Gauss on each of the 4 sub-squares and on each half of an edge
};

}  // namespace iga
