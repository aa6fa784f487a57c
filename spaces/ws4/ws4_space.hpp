#pragma once
/// @file
/// Ws4Space: C³ quartic Wang–Shi splines S₄³(T_WS4) on a triangulation, as an Argyris-style
/// Hermite finite element (WS4 notes §8).
///
/// Global basis (dimension 10 n_V + 6 n_E + 3 n_T), numbered vertices, then edges, then triangles:
///  - vertex v, 10 functions at 10 v + k: h^(a+b) D_{d1}^a D_{d2}^b u(v) in the order (a, b) =
///    (0,0), (1,0), (0,1), (2,0), (1,1), (0,2), (3,0), (2,1), (1,2), (0,3), with the vertex frame
///    (d1, d2) = (x, y) at interior vertices. At boundary vertices the frame follows the boundary:
///    d1, d2 are the unit directions of the two boundary edges at a corner, the unit tangent and
///    normal on a straight part. Then the trace on a boundary edge involves only D_t^j data of its
///    end vertices, and the trace of ∂_n u only D_t^j D_n data (notes §8.7), so the generic boundary
///    projection constrains exactly those functions, also on slanted boundaries;
///  - edge e = (a, b), a < b, 6 functions at 10 n_V + 6 e + k: with t = (x_b - x_a)/|x_b - x_a|,
///    n = (-t_y, t_x) and e(s) = x_a + s (x_b - x_a):
///    h ∂_n u(e(½)), h² ∂²_n u(e(¼)), h² ∂²_n u(e(¾)), h³ ∂³_n u(e(¼)), h³ ∂³_n u(e(½)), h³ ∂³_n u(e(¾));
///  - triangle t, 3 functions at 10 n_V + 6 n_E + 3 t + k: u at the reference points
///    (3/8, 1/4), (3/8, 3/8), (1/4, 3/8) (the paper's v3, v1, v2).
/// h is the mesh size (scaling keeps the orders of the unknowns comparable).
///
/// Element t (reference triangle -> (P0, P1, P2) affinely) has 51 active functions in the order:
/// vertex P0 (10), P1 (10), P2 (10), local edge 0 = P0P1 (6), 1 = P1P2 (6), 2 = P2P0 (6), interior (3).
/// Its local basis is the 51 reference simplex splines B_i; the extraction C_K (51 x 51) gives the
/// active function m as Σ_i C_K(i, m) B_i, C_K = G_K^{-1} with G_K(m, i) = (DOF functional m)(B_i),
/// computed without inversion as C_K = A⁻¹ T_K (exact A⁻¹, T_K from the corners; notes §8.2–8.3,
/// ws4_hermite_transform.hpp). Both neighbours of an edge use the same normal and points, hence C³
/// (notes §2.3).
///
/// Built on some elements (BuildsOnElements): the skeleton is the triangulation, the vertex frames
/// and the numbering above (all O(mesh), shared by the spaces built from it); the per-element data
/// are the shape classes of the built elements and their extractions C_K (a 51 x 51 matrix per
/// class: one per element on an unstructured mesh, 20.8 kB), computed for the built elements only.


#include "spaces/element_core.hpp"
#include "spaces/gauss_rule_cache.hpp"
#include "spaces/builds_on_elements.hpp"
#include "spaces/space.hpp"
#include "spaces/ws4/triangulation.hpp"
#include "spaces/ws4/ws4_hermite_transform.hpp"
#include "spaces/ws4/ws4_shape_classes.hpp"

namespace iga::ws4 {

/// Its evaluator is a specialisation (ws4_evaluator.hpp): one function and load vectors piece by
/// piece; make_generic_evaluator evaluates the explicit core through the generic path.
class Ws4Space final : public Space, public FastEvaluator, public BuildsOnElements {
 public:
  static constexpr int dofs_per_vertex = 10, dofs_per_edge = 6, dofs_per_triangle = 3, dofs_per_element = 51;

  /// The space on `mesh`; `description` names the domain in parameters().
  /// The space on `mesh`; `description` names the domain in parameters(). With
  /// SpaceExtent::skeleton no element is built on (build_on adds the extractions of some).
  explicit Ws4Space(Triangulation mesh, std::string description = "triangulation",
                    SpaceExtent extent = SpaceExtent::whole);

  ~Ws4Space() override;

  /// Facts: type "ws4"; parameters triangles, vertices, edges, domain; degree 4, C3 across
  /// macro-edges (note §2.3), affine; error rules of degree 2p on each of the 342 pieces (see the
  /// constructor); drawn on its pieces (Space::sample_cell), so that linear cells never straddle
  /// one; boundary parts of the triangulation (InputError for an unknown name).
  std::unique_ptr<Evaluator> make_evaluator() const override;
  /// The explicit core: the 51 reference simplex splines, C_K, the affine map.
  std::unique_ptr<Evaluator> make_generic_evaluator() const override;
  void element_dofs(int element, std::vector<int>& out) const override;

  /// triangle_rule(degree) on each of the 342 fan triangles of the WS4 split (shared by all elements).
  RulePtr quadrature(int element, int degree) const override;
  /// Gauss rule on each quarter of the edge (the pieces of the split along it).
  RulePtr edge_quadrature(int element, int edge, int degree) const override;

  /// C_Kᵀ K_B C_K from the universal reference matrices (ws4_closed_forms.hpp).
  const ClosedForms* closed_forms() const override;

  /// The space on the same skeleton with the extractions of `elements` (increasing) only.
  SpacePtr build_on(const std::vector<int>& elements) const override;
  bool built_on(int element) const override { return classes_.of_element[element] >= 0; }

  const Triangulation& mesh() const { return *mesh_; }
  /// J = [P1 - P0, P2 - P0] of element t.
  Eigen::Matrix2d jacobian(int element) const;
  /// Extraction C_K of element t (51 x 51, see the file comment), shared by its shape class.
  /// std::logic_error for an element not built on.
  const Eigen::MatrixXd& extraction(int element) const { return class_extraction_[class_of(element)]; }
  /// Elements with equal extraction and element matrices (translates of each other with the same
  /// frames, edge orientations and scales; ws4_shape_classes.hpp), among the built elements (the
  /// others' class is -1).
  const ShapeClasses& shape_classes() const { return classes_; }
  /// The shape class of a built element; std::logic_error for another.
  int class_of(int element) const {
    const int c = classes_.of_element[element];
    if (c < 0) not_built(element);
    return c;
  }
  /// G_K: the 51 DOF functionals of element t applied to the 51 reference B_i (rows: functionals);
  /// C_K G_K = I (an independent route to the extraction, for tests).
  Eigen::MatrixXd element_functionals(int element) const;

  /// Corners, frames, edge orientations and DOF scales of element t (ws4_exact_extraction's input).
  ElementDofGeometry dof_geometry(int element) const;

  /// Cartesian derivatives ∂x^a ∂y^b f(x) for a + b <= 3, indexed like the vertex DOFs
  /// (0: f, 1: f_x, 2: f_y, 3: f_xx, 4: f_xy, 5: f_yy, 6: f_xxx, 7: f_xxy, 8: f_xyy, 9: f_yyy).
  using Jet3 = std::function<std::array<double, 10>(const Point2& x)>;
  /// Global coefficients of the Hermite interpolant of f (exact for quartics).
  Eigen::VectorXd interpolate(const Jet3& f) const;

 private:
  struct Core;
  /// The space on `skeleton`'s mesh and frames, built on `elements`.
  Ws4Space(const Ws4Space& skeleton, const std::vector<int>& elements);
  void compute_vertex_frames();
  /// Shape classes, extractions and closed forms of `elements` (increasing).
  void build_extractions(const std::vector<int>& elements);
  [[noreturn]] void not_built(int element) const;
  /// Boundary edges of part `part` of the triangulation (-1: every boundary edge).
  std::vector<BoundaryEdge> part_edges(int part) const;

  std::shared_ptr<const Triangulation> mesh_;
  std::string description_;
  double mesh_size_ = 0.0;  ///< longest edge; also the h that scales the derivative DOFs
  ShapeClasses classes_;
  std::vector<Eigen::MatrixXd> class_extraction_;
  std::unique_ptr<const ClosedForms> closed_forms_;
  std::shared_ptr<const std::vector<Eigen::Matrix2d>> vertex_frame_;
  GaussRuleCache rules_{4};  ///< edges: Gauss on each quarter (the pieces of the split along it)
};

}  // namespace iga::ws4
