#pragma once
/// @file
/// The one interface every spline space of iga-run implements.
///
/// Vocabulary (used with these meanings everywhere in the project):
///  - *element*: a cell of the space's mesh, numbered 0..num_elements()-1. Each element has a
///    reference cell (unit square or unit triangle, see quadrature_rule.hpp) and a map from it to
///    physical coordinates. A macro-element (e.g. WS4) is one element whose polynomial pieces are
///    sub-regions of its reference cell.
///  - *global basis function* / *global index*: a basis function of the space, 0..dimension()-1.
///    These are the unknowns of the linear system before boundary conditions.
///  - *local basis*: the simple basis an element is built on (Bernstein, B-spline, simplex spline).
///    A space stores an *extraction*: the active global functions of an element as linear
///    combinations of its local basis. The local basis never appears in this interface.
///  - *free / constrained*: after boundary conditions, a global function is constrained when its
///    coefficient is fixed by Dirichlet-type data, free otherwise (see assembly/boundary_conditions).
///
/// Thread safety: a Space is immutable once built and may be shared by threads. Per-thread state
/// (scratch arrays, reference tables) lives in an Evaluator, one per thread.

#include <Eigen/Core>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "config/double_double.hpp"  // kept: code above spaces/ reaches DoubleDoubleMatrix through here
#include "spaces/point_values.hpp"
#include "quadrature/quadrature_rule.hpp"
#include "spaces/bilinear_form.hpp"

namespace iga {

enum class CellShape { quadrilateral, triangle };

/// Number of edges of the reference cell.
int num_edges(CellShape shape);
/// Point of edge `edge` of the reference cell at parameter t in [0,1]. Edges run counterclockwise:
/// quadrilateral 0: (t,0), 1: (1,t), 2: (1-t,1), 3: (0,1-t); triangle 0: (t,0), 1: (1-t,t), 2: (0,1-t).
Point2 reference_edge_point(CellShape shape, int edge, double t);
/// d(reference_edge_point)/dt: constant along each edge.
Point2 reference_edge_tangent(CellShape shape, int edge);
/// Edge rule in reference-cell coordinates from a rule on [0,1] (x coordinate); weights unchanged.
QuadratureRule edge_rule(CellShape shape, int edge, const QuadratureRule& rule_01);

/// Integration weights w_q |det J(x_q)| of `rule` on an element whose geometry is in `geometry`
/// (on a surface in 3D, w_q √det(JᵀJ)).
void integration_weights(const QuadratureRule& rule, const PointValues& geometry, Eigen::VectorXd& jxw);

/// A boundary edge: edge `local_edge` of element `element`.
struct BoundaryEdge {
  int element = 0;
  int local_edge = 0;
};

/// A piece of interior edge shared by two elements: where edge `edge_a` of `element_a` and edge
/// `edge_b` of `element_b` coincide. With the edge parameters of reference_edge_point, the physical
/// point at s in [0,1] is at t = a0 + s (a1 - a0) on edge_a and at t = b0 + s (b1 - b0) on edge_b
/// (a linear correspondence; b0 > b1 where the edges run in opposite directions). A whole shared
/// edge has [a0, a1] = [0, 1]; a T-junction edge of a large cell meets several small cells, one
/// piece each, with [a0, a1] a sub-range of the large cell's edge.
struct InteriorEdge {
  int element_a = 0, edge_a = 0;
  double a0 = 0.0, a1 = 1.0;
  int element_b = 0, edge_b = 0;
  double b0 = 1.0, b1 = 0.0;
};

/// A piece of an element to draw: points in reference coordinates and linear sub-cells over them
/// (3 indices per triangle, 4 per quadrilateral). Used by the VTK writer.
struct SampleCell {
  std::vector<Point2> points;
  std::vector<std::vector<int>> cells;
};

/// Append to `cell` a uniform grid of the triangle (a, b, c) with `m` intervals per edge: its
/// (m+1)(m+2)/2 points and m² sub-triangles (points along shared edges are not merged).
void append_triangle_grid(SampleCell& cell, const Point2& a, const Point2& b, const Point2& c, int m);

/// A smooth surface as triangular Bézier patches with its construction report
/// (geometry/surface_patches.hpp); declared here so that the interface does not pull in geometry.
struct SurfacePatches;

class ClosedForms;  // spaces/closed_forms.hpp

/// What is fixed about a space when it is built. Each space fills one in its constructor and hands
/// it to Space::set_facts; Space answers the questions below from it (no virtual call, and a new
/// space cannot forget one).
struct SpaceFacts {
  std::string type;  ///< short type name as used in configs, e.g. "bspline"
  /// Parameters describing this instance (degree, regularity, elements, ...) for summaries.
  std::vector<std::pair<std::string, std::string>> parameters;
  int dimension = 0;     ///< number of global basis functions
  int num_elements = 0;
  /// One shape for every element, or one per element (mixed meshes).
  std::vector<CellShape> cell_shapes;
  double mesh_size = 0.0;  ///< largest element diameter in physical coordinates (the h of tables)
  int degree = 0;          ///< polynomial degree of the local basis in reference coordinates
  /// The space is C^k in physical coordinates (biharmonic problems need k >= 1); 0 is the safe answer.
  int continuity = 0;
  /// Evaluator::evaluate_function provides update_laplacian_gradient and update_bilaplacian.
  bool higher_derivatives = false;
  bool affine_elements = false;  ///< every element map is affine (a rule of degree 2p is exact for mass)
  /// 2 for planar spaces; 3 for spaces on surfaces in 3D, whose evaluators fill the 3D members of
  /// PointValues (x3, jacobian3, dz) and whose gradients are surface gradients.
  int ambient_dimension = 2;
  /// Degree of the rules for error norms and residual estimators; -1 means 2 degree + 4 (resolves
  /// the smooth exact data on an element of size h). A macro-element whose rule is composite over
  /// much smaller pieces may ask for less (WS4).
  int error_quadrature_degree = -1;
  /// Named boundary parts in the order they are listed, and every boundary edge ("all"), each in
  /// the order the space numbers them (the order of boundary sums).
  std::vector<std::pair<std::string, std::vector<BoundaryEdge>>> boundary_parts;
  std::vector<BoundaryEdge> all_boundary_edges;
  /// Spaces on a smooth surface built from a triangle mesh: that surface's patches and report.
  std::shared_ptr<const SurfacePatches> surface_patches;
  /// Macro-elements: the polynomial pieces of every element's reference cell as triangles over
  /// shared points, so that drawings interpolate linearly only inside a piece. Empty: one piece.
  SampleCell pieces;
  /// The `g1_jump` column: spaces whose C1 continuity comes from gluing conditions across
  /// interfaces (G1 constructions), where it holds to round-off only, report the largest gradient
  /// jump at this many equispaced points of every interior edge piece (gradient_jump.hpp); 0: none.
  int gradient_jump_samples = 0;
  /// With pieces: sample_cell subdivides each piece into m² triangles, m = resolution / pieces_across
  /// (an edge of the reference cell crosses about pieces_across pieces); m <= 1 draws the pieces.
  int pieces_across = 1;
};

/// A capability of some spaces (T-meshes): adaptive local refinement. Kept off Space so that the
/// interface lists only what every space answers; Space::refined asks for it.
class LocallyRefinable {
 public:
  virtual ~LocallyRefinable() = default;
  /// A new space on a mesh where every element in `marked_elements` is refined (and possibly more
  /// elements, to keep the mesh valid for the space). Element numbers are unrelated to this one's.
  virtual std::shared_ptr<const class Space> refine(const std::vector<int>& marked_elements) const = 0;
};

/// Spaces are held by SpacePtr; enable_shared_from_this lets code that is handed a `const Space&`
/// (a study's LevelSink) keep the space alive beyond the call.
class Space : public std::enable_shared_from_this<Space> {
 public:
  virtual ~Space() = default;

  /// Per-thread evaluation of the active functions of an element. May cache reference tables
  /// keyed by the address of the rule it is given (rules are shared through RulePtr).
  class Evaluator {
   public:
    explicit Evaluator(const Space& space) : space_(space) {}
    virtual ~Evaluator() = default;
    /// Fill out.dofs, out.x, out.jacobian and the arrays requested by `flags` at the reference
    /// points of `points` (weights are ignored).
    virtual void evaluate(int element, const QuadratureRule& points, unsigned flags, PointValues& out) = 0;

    /// u_h = Σ_i coefficients(i) N_i (coefficients: one per global function, dimension() entries)
    /// and, per `flags`, its physical gradient and Hessian at the points of `points`. `geometry`
    /// receives at least dofs, x and jacobian (other arrays are scratch). Takes the element's
    /// coefficients and calls evaluate_element_function.
    void evaluate_function(int element, const QuadratureRule& points, const Eigen::VectorXd& coefficients,
                           unsigned flags, PointValues& geometry, FunctionValues& out);
    /// The same from the coefficients of the element's active functions alone (element_dofs
    /// order), so that a caller holding only some coefficients (a SpacePart's) takes the same
    /// path. Evaluators contract the coefficients first (one table product instead of one per
    /// active function).
    virtual void evaluate_element_function(int element, const QuadratureRule& points,
                                           const Eigen::VectorXd& element_coefficients, unsigned flags,
                                           PointValues& geometry, FunctionValues& out) = 0;

    /// Geometry for integrate_values: fills out.dofs, out.x and out.jacobian, plus whatever the
    /// space's integrate_values reads from `out`.
    virtual void evaluate_geometry(int element, const QuadratureRule& points, PointValues& out) = 0;

    /// The transposed evaluation (load vectors): local(i) = Σ_q weights(q) N_i(x_q), i in
    /// element_dofs order, for point weights that already include f(x_q) and JxW. `geometry` is the
    /// output of evaluate_geometry(element, points, geometry).
    virtual void integrate_values(int element, const QuadratureRule& points, const PointValues& geometry,
                                  const Eigen::VectorXd& weights, Eigen::VectorXd& local) = 0;

   private:
    const Space& space_;
    std::vector<int> dofs_;  // scratch of evaluate_function
    Eigen::VectorXd element_coefficients_;
  };
  virtual std::unique_ptr<Evaluator> make_evaluator() const = 0;

  /// Global indices of the functions active on `element`, in the order Evaluator::evaluate uses.
  virtual void element_dofs(int element, std::vector<int>& out) const = 0;

  /// A rule on element's reference cell exact for polynomials of degree `degree` on every
  /// polynomial piece of the element (a macro-element integrates sub-region by sub-region).
  virtual RulePtr quadrature(int element, int degree) const = 0;
  /// A rule on edge `edge` of the element's reference cell (weights w.r.t. the edge parameter),
  /// exact for polynomials of degree `degree` on every piece of the edge.
  virtual RulePtr edge_quadrature(int element, int edge, int degree) const = 0;

  /// Element matrices without quadrature, for spaces that have them (spaces/closed_forms.hpp).
  /// nullptr (the default): the assembler integrates with quadrature.
  virtual const ClosedForms* closed_forms() const { return nullptr; }

  /// Optional: every interior edge piece (each once), for estimators that need both sides of an
  /// edge (the normal-derivative jumps of the residual estimator). Empty (the default) means the
  /// space cannot locate the element across its edges; callers then treat jumps as unavailable.
  virtual std::vector<InteriorEdge> interior_edges() const { return {}; }

  // Facts fixed when the space was built (SpaceFacts).
  const SpaceFacts& facts() const { return facts_; }
  const std::string& type() const { return facts_.type; }
  const std::vector<std::pair<std::string, std::string>>& parameters() const { return facts_.parameters; }
  int dimension() const { return facts_.dimension; }
  int num_elements() const { return facts_.num_elements; }
  CellShape cell_shape(int element) const {
    return facts_.cell_shapes.size() == 1 ? facts_.cell_shapes[0] : facts_.cell_shapes[element];
  }
  double mesh_size() const { return facts_.mesh_size; }
  int degree() const { return facts_.degree; }
  int continuity() const { return facts_.continuity; }
  bool higher_derivatives() const { return facts_.higher_derivatives; }
  bool affine_elements() const { return facts_.affine_elements; }
  int ambient_dimension() const { return facts_.ambient_dimension; }
  int error_quadrature_degree() const {
    return facts_.error_quadrature_degree >= 0 ? facts_.error_quadrature_degree : 2 * facts_.degree + 4;
  }
  /// nullptr for every space that is not on a surface built from a triangle mesh.
  const std::shared_ptr<const SurfacePatches>& surface_patches() const { return facts_.surface_patches; }

  /// Names of the boundary parts (e.g. left, right, bottom, top). "all" is implied.
  std::vector<std::string> boundary_names() const;
  /// Boundary edges of the named part; "all" returns every boundary edge. InputError for an unknown name.
  std::vector<BoundaryEdge> boundary_edges(const std::string& name) const;

  /// The largest jump of the physical (surface) gradient of Σ c_i N_i across interior element
  /// edges (gradient_jump.hpp) for spaces with SpaceFacts::gradient_jump_samples, at round-off for
  /// a C1 space: the `g1_jump` column of convergence.csv. nullopt leaves the column empty.
  std::optional<double> max_gradient_jump(const Eigen::VectorXd& coefficients) const;

  /// Adaptive refinement (LocallyRefinable) when the space has it, else nullptr.
  std::shared_ptr<const Space> refined(const std::vector<int>& marked_elements) const;

  /// Sub-cells to draw element `element` with about `resolution` samples per edge: a uniform grid
  /// of the reference cell, or of each of its pieces (SpaceFacts::pieces).
  SampleCell sample_cell(int element, int resolution) const;

 protected:
  /// Called once by each space's constructor, after it has computed what the facts need.
  void set_facts(SpaceFacts facts) { facts_ = std::move(facts); }

 private:
  SpaceFacts facts_;
};

using SpacePtr = std::shared_ptr<const Space>;

}  // namespace iga
