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

#include "config/double_double.hpp"
#include "spaces/bilinear_form.hpp"
#include "spaces/point_values.hpp"
#include "quadrature/quadrature_rule.hpp"

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

/// Spaces are held by SpacePtr; enable_shared_from_this lets code that is handed a `const Space&`
/// (a study's LevelSink) keep the space alive beyond the call.
class Space : public std::enable_shared_from_this<Space> {
 public:
  virtual ~Space() = default;

  /// Per-thread evaluation of the active functions of an element. May cache reference tables
  /// keyed by the address of the rule it is given (rules are shared through RulePtr).
  class Evaluator {
   public:
    virtual ~Evaluator() = default;
    /// Fill out.dofs, out.x, out.jacobian and the arrays requested by `flags` at the reference
    /// points of `points` (weights are ignored).
    virtual void evaluate(int element, const QuadratureRule& points, unsigned flags, PointValues& out) = 0;

    /// u_h = Σ_i coefficients(i) N_i (coefficients: one per global function, dimension() entries)
    /// and, per `flags`, its physical gradient and Hessian at the points of `points`. `geometry`
    /// receives at least dofs, x and jacobian (other arrays are scratch). The default evaluates all
    /// active functions and contracts them; a space with a large extraction overrides it and
    /// contracts the coefficients first (one table product instead of n).
    virtual void evaluate_function(int element, const QuadratureRule& points, const Eigen::VectorXd& coefficients,
                                   unsigned flags, PointValues& geometry, FunctionValues& out);

    /// Geometry for integrate_values: fills out.dofs, out.x and out.jacobian, plus whatever the
    /// space's integrate_values reads from `out` (the default also fills out.value).
    virtual void evaluate_geometry(int element, const QuadratureRule& points, PointValues& out);

    /// The transposed evaluation (load vectors): local(i) = Σ_q weights(q) N_i(x_q), i in
    /// element_dofs order, for point weights that already include f(x_q) and JxW. `geometry` is the
    /// output of evaluate_geometry(element, points, geometry). The default is geometry.value * weights.
    virtual void integrate_values(int element, const QuadratureRule& points, const PointValues& geometry,
                                  const Eigen::VectorXd& weights, Eigen::VectorXd& local);
  };
  virtual std::unique_ptr<Evaluator> make_evaluator() const = 0;

  /// 2 for planar spaces; 3 for spaces on surfaces in 3D, whose evaluators fill the 3D members
  /// of PointValues (x3, jacobian3, dz) and whose gradients are surface gradients.
  virtual int ambient_dimension() const { return 2; }

  /// Spaces on a smooth surface built from a triangle mesh: that surface's patches and report,
  /// for the outputs (surface files, summary.json). nullptr (the default) for every other space.
  virtual std::shared_ptr<const SurfacePatches> surface_patches() const { return nullptr; }
  /// Short type name as used in configs, e.g. "bspline".
  virtual std::string type() const = 0;
  /// Parameters describing this instance (degree, regularity, elements, ...) for summaries.
  virtual std::vector<std::pair<std::string, std::string>> parameters() const = 0;

  /// Number of global basis functions.
  virtual int dimension() const = 0;
  /// Global indices of the functions active on `element`, in the order Evaluator::evaluate uses.
  /// The default evaluates at one point; spaces override it with a direct lookup.
  virtual void element_dofs(int element, std::vector<int>& out) const;
  virtual int num_elements() const = 0;
  virtual CellShape cell_shape(int element) const = 0;
  /// Largest element diameter in physical coordinates (the h of convergence tables).
  virtual double mesh_size() const = 0;
  /// Polynomial degree of the local basis in reference coordinates (drives quadrature choices).
  virtual int degree() const = 0;
  /// Global smoothness: the space is C^k (k = continuity()) in physical coordinates. Biharmonic
  /// problems need k >= 1 (H2-conforming). The default 0 is the safe answer for a new space.
  virtual int continuity() const { return 0; }
  /// True when evaluate_function provides update_laplacian_gradient and update_bilaplacian (third
  /// and fourth derivatives, for the biharmonic residual estimator). Default false.
  virtual bool higher_derivatives() const { return false; }
  /// True when every element map is affine (then a rule of degree 2p is exact for mass matrices).
  virtual bool affine_elements() const = 0;
  /// Degree of the rules for error norms and residual estimators, whose integrands hold the smooth
  /// exact data as well as u_h: 2p + 4 resolves them on an element of size h. A macro-element
  /// whose rule is composite over much smaller sub-regions may ask for less (see WS4).
  virtual int error_quadrature_degree() const { return 2 * degree() + 4; }

  /// A rule on element's reference cell exact for polynomials of degree `degree` on every
  /// polynomial piece of the element (a macro-element integrates sub-region by sub-region).
  virtual RulePtr quadrature(int element, int degree) const = 0;
  /// A rule on edge `edge` of the element's reference cell (weights w.r.t. the edge parameter),
  /// exact for polynomials of degree `degree` on every piece of the edge.
  virtual RulePtr edge_quadrature(int element, int edge, int degree) const = 0;

  /// Names of the boundary parts (e.g. left, right, bottom, top). "all" is implied.
  virtual std::vector<std::string> boundary_names() const = 0;
  /// Boundary edges of the named part; "all" returns every boundary edge.
  virtual std::vector<BoundaryEdge> boundary_edges(const std::string& name) const = 0;

  /// Optional fast path: the element matrix of `form` without quadrature (e.g. a combination of
  /// reference matrices of an affine-invariant basis), rows and columns in element_dofs order.
  /// Return false (the default) and the assembler integrates with quadrature. Must be thread-safe.
  virtual bool closed_form_element_matrix(int /*element*/, BilinearForm /*form*/, Eigen::MatrixXd& /*local*/) const {
    return false;
  }
  /// The same closed form in long double, not rounded to double: the residuals of iterative
  /// refinement need the matrix beyond double precision (assembly/split_matrix.hpp). The default
  /// widens closed_form_element_matrix; a space with a closed form should override it.
  virtual bool closed_form_element_matrix_extended(int element, BilinearForm form,
                                                   Eigen::Matrix<long double, Eigen::Dynamic, Eigen::Dynamic>& local) const;
  /// The same closed form in double-double, for fourth-order problems whose residuals need the
  /// matrix beyond long double (assembly/split_matrix.hpp). The default widens the long double one.
  virtual bool closed_form_element_matrix_double_double(int element, BilinearForm form, DoubleDoubleMatrix& local) const;
  /// Called once before an element loop over the double-double closed forms, outside any parallel
  /// region: a space whose closed forms share tables (reference matrices, matrices of shape
  /// classes) builds them here with every thread, rather than inside the loop, where the first
  /// element to need them builds them on one thread while the others wait. Default: nothing.
  virtual void prepare_closed_forms_double_double(BilinearForm /*form*/) const {}
  /// The double-double closed form of `element` when it is a matrix shared by several elements
  /// (valid while the space lives): the assembler reads it in place instead of copying it. Null
  /// (the default) when the element has no shared matrix; then closed_form_element_matrix_double_double.
  virtual const DoubleDoubleMatrix* shared_closed_form_double_double(int /*element*/, BilinearForm /*form*/) const {
    return nullptr;
  }

  /// The largest jump of the physical gradient of Σ c_i N_i across interior element edges, for
  /// spaces that can locate both sides of their edges (a C1 space has it at round-off). Reported
  /// as the `g1_jump` column of convergence.csv; nullopt (the default) leaves the column empty.
  virtual std::optional<double> max_gradient_jump(const Eigen::VectorXd& /*coefficients*/) const {
    return std::nullopt;
  }

  /// Optional: every interior edge piece (each once), for estimators that need both sides of an
  /// edge (the normal-derivative jumps of the residual estimator). Empty (the default) means the
  /// space cannot locate the element across its edges; callers then treat jumps as unavailable.
  virtual std::vector<InteriorEdge> interior_edges() const { return {}; }

  /// Optional adaptive refinement: a new space on a mesh where every element in `marked_elements`
  /// is refined (and possibly more elements, to keep the mesh valid for the space, e.g. an
  /// admissible T-mesh). Element numbers of the new space are unrelated to this one's.
  /// nullptr (the default) means the space does not support local refinement.
  virtual std::shared_ptr<const Space> refined(const std::vector<int>& /*marked_elements*/) const { return nullptr; }

  /// Sub-cells to draw element `element` with about `resolution` samples per edge.
  /// The default samples the reference cell uniformly.
  virtual SampleCell sample_cell(int element, int resolution) const;
};

using SpacePtr = std::shared_ptr<const Space>;

}  // namespace iga
