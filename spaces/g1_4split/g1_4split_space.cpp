#include "spaces/g1_4split/g1_4split_space.hpp"

#include <algorithm>
#include <cstdio>
#include <map>
#include <set>
#include <stdexcept>
#include <string>

#include "spaces/extracted_evaluator.hpp"
#include "spaces/g1/boundary_parts.hpp"
#include "spaces/g1_4split/face_function.hpp"
#include "spaces/g1_4split/g1_4split_meshes.hpp"
#include "spaces/g1_4split/fan_values.hpp"
#include "spaces/g1_4split/fair_geometry.hpp"
#include "spaces/g1_4split/g14_local_problems.hpp"
#include "spaces/g1_4split/line_gluing.hpp"
#include "spaces/g1_4split/nested_geometry.hpp"

namespace iga {

namespace {

/// The explicit core (element_core.hpp): every face's tensor B-spline with the knot 1/2 (one kind),
/// the sparse extraction of g1_4split_basis.hpp and the isoparametric map, whose coefficients go
/// through the same tables.
struct G14Core {
  using Jet = GeometryJet;
  static constexpr bool identity = false;
  const G14Space& space;
  mutable NestedGeometry::Path path{};  ///< face_geometry's walk down the level-0 map

  int kind(int /*e*/) const { return 0; }
  int tabulate(int /*kind*/, const std::vector<Point2>& points, int /*order*/, LocalTables& t) const {
    tensor_tables(space.basis().bspline, points, t);
    return 2;
  }
  std::vector<int> active(int e) const {
    std::vector<int> out;
    space.element_dofs(e, out);
    return out;
  }
  Extraction extraction(int e) const { return extraction_view(space.extraction(e)); }
  void map(int e, const QuadratureRule& rule, const LocalTables& t, int /*order*/, std::vector<Jet>& jets) const {
    const int q = rule.size();
    Eigen::Matrix<double, 6, Eigen::Dynamic> X(6, q), Y(6, q);
    const Eigen::VectorXd *x, *y;
    space.face_geometry(e, path, x, y);
    for (int d = 0; d < 6; ++d) {
      X.row(d) = x->transpose() * t[d];
      Y.row(d) = y->transpose() * t[d];
    }
    jets.resize(q);
    for (int p = 0; p < q; ++p) {
      GeometryJet& j = jets[p];
      j.x = Point2(X(0, p), Y(0, p));
      j.jacobian << X(1, p), X(2, p), Y(1, p), Y(2, p);
      j.hessian_x << X(3, p), X(4, p), X(4, p), X(5, p);
      j.hessian_y << Y(3, p), Y(4, p), Y(4, p), Y(5, p);
    }
  }
};

/// The level-0 map (or every level's, for `rebuild`) by the chosen fit; `order` of the fair energy.
FaceGeometry fitted_geometry(const G14Basis& basis, const QuadTopology& topology, const PatchMesh& mesh, GeometryFit fit,
                             int order = 3) {
  FairFit fair;
  fair.order = order;
  return fit == GeometryFit::fair ? fair_geometry(basis, topology, mesh, fair)
                                  : project_geometry(basis, bilinear_geometry(mesh, basis.bspline));
}

/// The smallest certified det J bound over the faces (check_face_geometry's margin below).
constexpr double kCertifiedJacobian = 1e-8;
double level0_jacobian_bound(const SplitBSpline& b, const FaceGeometry& g) {
  double bound = 1e300;
  for (std::size_t f = 0; f < g.x.size(); ++f) bound = std::min(bound, certified_jacobian_bound(b, g.x[f], g.y[f]));
  return bound;
}

/// The level-0 gluing, basis and fitted map, and how the gluing was built.
struct Level0 {
  std::vector<SplitGluing> gluing;
  G14Basis basis;
  FaceGeometry geometry;
  LineGluingReport report;
  std::string values;  ///< which vertex values the lines gluing took, and why (`lines` only)
};

Level0 level0(const PatchMesh& mesh, const QuadTopology& topology, std::vector<SplitGluing> gluing,
              const LineGluingReport& report, const G14Options& options) {
  Level0 out{std::move(gluing), {}, {}, report, {}};
  out.basis = build_g14_basis(topology, out.gluing, options.degree, options.regularity);
  out.geometry = fitted_geometry(out.basis, topology, mesh, options.fit);
  return out;
}

/// The default gluing `lines` of a planar mesh with its map. The least-squares map keeps the
/// vertex values from the mesh's own fans (planar_line_gluing) it was measured with. With the fair
/// map both choices of vertex values are built — the mesh fans and the symmetric values
/// 2cos(2π/n), 2cos(α/F) (line_gluing) — and the one whose fair map is certified regular and
/// spreads each face's area more evenly (the smaller largest_jacobian_ratio) is taken. Neither
/// wins on every mesh: the plate's H2 at equal DOFs is 3.6× / 9.7× / 69× `g1`'s on the Gmsh
/// pentagon / moved / bumped 3 × 3 grid with the symmetric values against 9× / 36× / 236× with the
/// fans, and 10× lower with the fans on `5p_square`; the ratio picks the better one on all 13
/// meshes measured (docs/spaces/g1_4split.md, "Which gluing values with the fair map"). Where the
/// two maps are the same (both the bilinear map, e.g. the split fans) the fans are kept.
Level0 default_planar_level0(const PatchMesh& mesh, const QuadTopology& topology, const G14Options& options) {
  LineGluingReport fans_report, symmetric_report;
  std::vector<SplitGluing> fans = planar_line_gluing(mesh, topology, &fans_report);
  Level0 a = level0(mesh, topology, std::move(fans), fans_report, options);
  if (options.fit != GeometryFit::fair || !fans_report.mesh_fans) {  // (no mesh fans: it is the symmetric gluing)
    a.values = fans_report.mesh_fans ? "mesh fans" : "symmetric";
    return a;
  }
  std::vector<SplitGluing> symmetric =
      line_gluing(topology, symmetric_vertex_values(topology, vertex_angles(mesh)), &symmetric_report);
  Level0 b = level0(mesh, topology, std::move(symmetric), symmetric_report, options);
  const double ra = largest_jacobian_ratio(a.basis.bspline, a.geometry);
  const double rb = largest_jacobian_ratio(b.basis.bspline, b.geometry);
  const bool ca = level0_jacobian_bound(a.basis.bspline, a.geometry) > kCertifiedJacobian;
  const bool cb = level0_jacobian_bound(b.basis.bspline, b.geometry) > kCertifiedJacobian;
  const bool symmetric_wins = cb && (!ca || rb < ra * (1.0 - 1e-6));  // equal maps: keep the fans
  const bool other_certified = symmetric_wins ? ca : cb;
  const char* other = symmetric_wins ? "mesh fans" : "symmetric values";
  char buf[160];
  if (other_certified)
    std::snprintf(buf, sizeof buf, "%s (det J ratio %.3g, %.3g with the %s)", symmetric_wins ? "symmetric" : "mesh fans",
                  symmetric_wins ? rb : ra, symmetric_wins ? ra : rb, other);
  else
    std::snprintf(buf, sizeof buf, "%s (det J ratio %.3g; the map with the %s is not certified regular)",
                  symmetric_wins ? "symmetric" : "mesh fans", symmetric_wins ? rb : ra, other);
  Level0& chosen = symmetric_wins ? b : a;
  chosen.values = buf;
  return std::move(chosen);
}

}  // namespace

G14Space::G14Space(const PatchMesh& coarse, const G14Options& options) : options_(options) {
  PatchMesh mesh = coarse;
  QuadTopology topology = quad_topology(mesh);
  Level0 start = options.blending == Blending::lines
                     ? default_planar_level0(mesh, topology, options)
                     : level0(mesh, topology, symmetric_gluing(topology, options.blending, vertex_angles(mesh)), {}, options);
  const LineGluingReport lines = start.report;
  const std::string gluing_values = start.values;
  gluing_ = std::move(start.gluing);
  basis_ = std::move(start.basis);
  geometry_ = std::move(start.geometry);
  double jacobian = level0_jacobian_bound(basis_.bspline, geometry_);  // refinement keeps the map
  GeometryFit fit = options.fit;
  int order = 3;  // of the fair energy
  std::string fit_name = fit == GeometryFit::fair ? "fair" : "least_squares";
  if (fit == GeometryFit::fair && jacobian <= kCertifiedJacobian) {
    // Where the D3 map folds (Gmsh's pentagon at mesh size 0.2 with the mesh-fan gluing; no mesh
    // tried with the gluing the default takes) the thin-plate one (D2), stiffer
    // against folding, then (default fit only: asked for, `fair` is refused below) the
    // least-squares map (Gmsh's L-shape); summary.json says which.
    order = 2;
    geometry_ = fitted_geometry(basis_, topology, mesh, fit, order);
    jacobian = level0_jacobian_bound(basis_.bspline, geometry_);
    fit_name = "fair, thin plate (the D3 map is not certified regular)";
    if (jacobian <= kCertifiedJacobian && !options.fit_required) {
      fit = GeometryFit::least_squares;
      geometry_ = fitted_geometry(basis_, topology, mesh, fit);
      jacobian = level0_jacobian_bound(basis_.bspline, geometry_);
      fit_name = "least_squares (the fair map is not certified regular)";
    }
  }
  // A skeleton of a nested level keeps the level-0 map only (nested_geometry.hpp).
  const bool lazy = options.nested && options.level > 0 && options.extent == SpaceExtent::skeleton;
  for (int l = 0; l < options.level; ++l) {
    PatchMesh finer = mesh.refined();
    QuadTopology fine = quad_topology(finer);
    if (options.nested) {
      gluing_ = inherited_gluing(topology, gluing_, fine);
      if (!lazy) geometry_ = subdivide_geometry(basis_.bspline, geometry_);
      if (l + 1 < options.level || options.extent == SpaceExtent::skeleton) {
        // A level on the way, or a skeleton: its errors (NotSeparable) and counts, no basis kept
        // (the same lifts as build_g14_basis, one vertex at a time).
        G14Basis counted;
        counted.bspline = basis_.bspline;
        counted.numbering = G14LocalProblems(fine, gluing_, counted.bspline).count_functions();
        basis_ = std::move(counted);
      } else {
        basis_ = build_g14_basis(fine, gluing_, options.degree, options.regularity);
      }
    } else {
      G14Options rebuilt = options;
      rebuilt.fit = fit;
      Level0 next = options.blending == Blending::lines
                        ? default_planar_level0(finer, fine, rebuilt)
                        : level0(finer, fine, symmetric_gluing(fine, options.blending, vertex_angles(finer)), {}, rebuilt);
      gluing_ = std::move(next.gluing);
      basis_ = std::move(next.basis);
      geometry_ = order == 3 ? std::move(next.geometry) : fitted_geometry(basis_, fine, finer, fit, order);
    }
    mesh = std::move(finer);
    topology = std::move(fine);
  }
  if (lazy) {
    nested_ = std::make_shared<const NestedGeometry>(basis_.bspline, std::move(geometry_), options.level);
    geometry_ = {};
  }
  // Every face's map, in order (check_face_geometry's first failing face), and the mesh size: one
  // visit of each face (a skeleton subdivides each ancestor once).
  double mesh_size = 0.0;
  {
    NestedGeometry::Path path;
    for (int f = 0; f < topology.num_faces(); ++f) {
      const Eigen::VectorXd *x = lazy ? nullptr : &geometry_.x[f], *y = lazy ? nullptr : &geometry_.y[f];
      if (lazy) nested_->face(f, path, x, y);
      check_face_geometry(basis_.bspline, *x, *y, f, mesh.name(), fit == GeometryFit::fair);
      // Diameter: largest distance between samples of the face boundary.
      std::vector<Point2> pts;
      for (int j = 0; j < 4; ++j)
        for (int s = 0; s < 4; ++s) {
          const Point2 uv = reference_edge_point(CellShape::quadrilateral, j, s / 4.0);
          pts.emplace_back(face_jet(basis_.bspline, *x, uv)(0), face_jet(basis_.bspline, *y, uv)(0));
        }
      for (const Point2& a : pts)
        for (const Point2& b : pts) mesh_size = std::max(mesh_size, (a - b).norm());
    }
  }
  topology_ = std::make_shared<const QuadTopology>(std::move(topology));
  SpaceFacts facts;
  facts.type = "g1_4split";
  facts.parameters = {{"degree", std::to_string(options_.degree)},
                      {"regularity", std::to_string(options_.regularity)},
                      {"blending", blending_name(options_.blending)},
                      {"refinement", options_.nested ? "nested" : "rebuild"},
                      {"geometry_fit", fit_name},
                      {"faces", std::to_string(topology_->num_faces())},
                      {"domain", mesh.name()}};
  if (options_.blending == Blending::lines) {
    // How the gluing was built, and how far the fitted map is from degenerate (docs/spaces/g1_4split.md).
    facts.parameters.emplace_back("gluing_lines", lines.mesh_fans ? "mesh fans, " + std::to_string(lines.lines) +
                                                                          " chains through crossings"
                                                                    : std::to_string(lines.lines) + " lines, " +
                                                                          std::to_string(lines.zigzag_lines) + " zigzag");
    facts.parameters.emplace_back("gluing_values", gluing_values);
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3e", jacobian);
    facts.parameters.emplace_back("jacobian_bound", buf);
  }
  facts.dimension = basis_.numbering.dimension(topology_->num_faces());
  facts.num_elements = topology_->num_faces();
  facts.cell_shapes = {CellShape::quadrilateral};
  facts.degree = options_.degree;
  facts.continuity = 1;
  facts.gradient_jump_samples = 4 * options_.degree + 8;
  set_boundary_parts(mesh, facts);  // the level mesh is needed no more: not kept
  facts.mesh_size = mesh_size;
  set_facts(std::move(facts));
  if (options_.extent == SpaceExtent::skeleton) {  // the numbering stays, the local problems wait
    basis_.functions = {};
    basis_.face_dofs = {};
    basis_.extraction = {};
    slot_.assign(topology_->num_faces(), -1);
  } else {
    slot_.resize(topology_->num_faces());
    for (int f = 0; f < topology_->num_faces(); ++f) slot_[f] = f;
  }
}

G14Space::G14Space(std::shared_ptr<const G14Space> skeleton, const std::vector<int>& elements)
    : options_(skeleton->options_),
      topology_(skeleton->topology_),
      skeleton_(skeleton),
      slot_(skeleton->topology_->num_faces(), -1) {
  if (skeleton->nested_) {  // the built faces' maps from the level-0 map, in order
    NestedGeometry::Path path;
    for (int f : elements) {
      const Eigen::VectorXd *x, *y;
      skeleton->nested_->face(f, path, x, y);
      geometry_.x.push_back(*x);
      geometry_.y.push_back(*y);
    }
  }
  const QuadTopology& t = *topology_;
  basis_.bspline = skeleton->basis_.bspline;
  basis_.numbering = skeleton->basis_.numbering;
  const G14Numbering& n = basis_.numbering;
  std::vector<std::vector<int>> dofs(elements.size());
  for (std::size_t s = 0; s < elements.size(); ++s) {
    slot_[elements[s]] = static_cast<int>(s);
    n.face_functions(t, elements[s], dofs[s]);
  }
  G14FaceExtractions extractions(basis_.bspline.face_size(), slot_, std::move(dofs));
  // The entities whose functions live on these faces, and the systems of the edges at their vertices.
  std::set<int> vertices, edges;
  for (int f : elements)
    for (int j = 0; j < 4; ++j) {
      vertices.insert(t.face(f)[j]);
      edges.insert(t.face_edge(f, j));
    }
  const G14LocalProblems local(t, gluing(), basis_.bspline);
  std::map<int, G14EdgeSystem> systems;
  for (int v : vertices)
    for (int e : t.vertex_edges(v))
      if (!t.edge(e).boundary() && !systems.count(e)) systems.emplace(e, local.edge_system(e));
  const G14LocalProblems::SystemOf system = [&](int e) -> const G14EdgeSystem& { return systems.at(e); };
  // Each function's entries on the built faces, as the whole basis's extraction has them.
  const auto distribute = [&](const std::vector<BrokenFunction>& functions, int first, int expected, const char* what,
                              int entity) {
    if (static_cast<int>(functions.size()) != expected)
      throw std::logic_error("G14Space::build_on: " + std::string(what) + " " + std::to_string(entity) + " has " +
                             std::to_string(functions.size()) + " functions, the skeleton counted " +
                             std::to_string(expected));
    for (std::size_t i = 0; i < functions.size(); ++i)
      for (const auto& [index, x] : kept_entries(functions[i])) extractions.add(first + static_cast<int>(i), index, x);
  };
  for (int v : vertices)
    distribute(local.vertex_functions(v, system), n.vertex_first[v], n.vertex_first[v + 1] - n.vertex_first[v],
               "vertex", v);
  for (int e : edges)
    distribute(local.edge_functions(e, t.edge(e).boundary() ? nullptr : &systems.at(e)), n.edge_first[e],
               n.edge_first[e + 1] - n.edge_first[e], "edge", e);
  systems.clear();
  for (int f : elements)
    distribute(local.face_functions(f), n.edge_first.back() + f * n.per_face, n.per_face, "face", f);
  basis_.extraction = extractions.finish();
  set_facts(skeleton->facts());
}

void G14Space::face_geometry(int f, NestedGeometry::Path& path, const Eigen::VectorXd*& x,
                             const Eigen::VectorXd*& y) const {
  const G14Space& owner = skeleton_ ? *skeleton_ : *this;
  if (!owner.nested_) {
    x = &owner.geometry_.x[f];
    y = &owner.geometry_.y[f];
  } else if (slot_[f] >= 0) {  // built on f: its map is kept, by slot
    x = &geometry_.x[slot_[f]];
    y = &geometry_.y[slot_[f]];
  } else {
    owner.nested_->face(f, path, x, y);
  }
}

const Eigen::SparseMatrix<double>& G14Space::extraction(int element) const {
  if (slot_[element] < 0)
    throw std::logic_error("G14Space: element " + std::to_string(element) +
                           " was not built on (a space built on some elements is asked for another)");
  return basis_.extraction[slot_[element]];
}

void G14Space::element_dofs(int element, std::vector<int>& out) const {
  if (!basis_.face_dofs.empty()) out = basis_.face_dofs[element];
  else basis_.numbering.face_functions(*topology_, element, out);
}

SpacePtr G14Space::build_on(const std::vector<int>& elements) const {
  check_element_set(elements, topology_->num_faces(), "G14Space::build_on");
  // The data every element shares stay with the skeleton (this space's own, or its skeleton).
  const auto skeleton = skeleton_ ? skeleton_ : std::static_pointer_cast<const G14Space>(shared_from_this());
  return std::shared_ptr<const G14Space>(new G14Space(skeleton, elements));
}

std::unique_ptr<Space::Evaluator> G14Space::make_evaluator() const {
  return std::make_unique<ExtractedEvaluator<G14Core>>(*this, G14Core{*this});
}

std::vector<InteriorEdge> quad_interior_edges(const QuadTopology& t) {
  std::vector<InteriorEdge> out;
  for (int e = 0; e < t.num_edges(); ++e) {
    const QuadEdge& edge = t.edge(e);
    if (edge.boundary()) continue;
    InteriorEdge ie;
    const QuadSide a = edge.sides[0], b = edge.sides[1];
    const bool same = t.face(a.face)[a.local_edge] == t.face(b.face)[b.local_edge];
    ie.element_a = a.face;
    ie.edge_a = a.local_edge;
    ie.a0 = 0.0;
    ie.a1 = 1.0;
    ie.element_b = b.face;
    ie.edge_b = b.local_edge;
    ie.b0 = same ? 0.0 : 1.0;
    ie.b1 = same ? 1.0 : 0.0;
    out.push_back(ie);
  }
  return out;
}

}  // namespace iga
