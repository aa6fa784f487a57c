#include "spaces/g1_4split/g1_4split_surface_space.hpp"

#include <Eigen/Geometry>  // cross
#include <Eigen/LU>
#include <algorithm>
#include <stdexcept>

#include "config/errors.hpp"
#include "geometry/surface_jet.hpp"
#include "spaces/g1_4split/face_function.hpp"
#include "spaces/g1_4split/g1_4split_geometry.hpp"
#include "spaces/extracted_evaluator.hpp"

namespace iga {

namespace {

/// Lower bound of (x_u × x_v) · c / diameter² on one face, c the unit normal at the centre: the
/// Jacobian of the face's projection onto its centre tangent plane, certified like a planar map.
double face_fold_bound(const G14Surface& s, int f) {
  const SplitBSpline& b = s.basis.bspline;
  const std::array<Eigen::VectorXd, 3>& xyz = s.coefficients[f];
  const auto jet = face_map_jet(s, f, 0.5, 0.5);
  const Eigen::Vector3d &du = jet[1], &dv = jet[2];
  if (area_element(du, dv) == 0.0) return 0.0;
  const Eigen::Vector3d e1 = du.normalized(), e2 = unit_normal(du, dv).cross(e1);
  const Eigen::VectorXd p = e1(0) * xyz[0] + e1(1) * xyz[1] + e1(2) * xyz[2];
  const Eigen::VectorXd q = e2(0) * xyz[0] + e2(1) * xyz[1] + e2(2) * xyz[2];
  return certified_jacobian_bound(b, p, q);
}

}  // namespace

/// The explicit core (element_core.hpp): the planar space's local basis and extraction, and the
/// fitted surface's map, whose three coordinates go through the same tables.
struct G14SurfaceSpace::Core {
  using Jet = SurfaceJet;
  static constexpr bool identity = false;
  const G14Surface& surface;

  int kind(int /*e*/) const { return 0; }
  int tabulate(int /*kind*/, const std::vector<Point2>& points, int /*order*/, LocalTables& t) const {
    tensor_tables(surface.basis.bspline, points, t);
    return 2;
  }
  const std::vector<int>& active(int e) const { return surface.basis.face_dofs[e]; }
  Extraction extraction(int e) const { return extraction_view(surface.basis.extraction[e]); }
  void map(int e, const QuadratureRule& rule, const LocalTables& t, int order, std::vector<Jet>& jets) const {
    const int q = rule.size();
    const bool second = order >= 2;
    // Rows of X[c]: coordinate c of the map and its ξ, η, ξξ, ξη, ηη derivatives (tables' order).
    Eigen::Matrix<double, 6, Eigen::Dynamic> X[3];
    for (int c = 0; c < 3; ++c) {
      X[c].resize(6, q);
      const Eigen::VectorXd& coef = surface.coefficients[e][c];
      for (int d = 0; d < (second ? 6 : 3); ++d) X[c].row(d) = coef.transpose() * t[d];
    }
    jets.resize(q);
    for (int k = 0; k < q; ++k) {
      Eigen::Vector3d x;
      Eigen::Matrix<double, 3, 2> J;
      std::array<Eigen::Vector3d, 3> dd;
      for (int c = 0; c < 3; ++c) {
        x(c) = X[c](0, k);
        J(c, 0) = X[c](1, k);
        J(c, 1) = X[c](2, k);
        for (int ab = 0; ab < 3; ++ab) dd[ab](c) = X[c](3 + ab, k);
      }
      // The sign of n does not matter to the problems: H ∂_n u is the same for −n.
      fill_surface_jet(jets[k], x, J, second ? &dd : nullptr);
    }
  }
};

G14SurfaceSpace::G14SurfaceSpace(const QuadTopology& coarse, const std::vector<Eigen::Vector3d>& vertices,
                                 const G14Options& options, const FitTarget& onto, const std::string& onto_name)
    : options_(options), onto_name_(onto_name) {
  if (!options.nested) throw std::invalid_argument("G14SurfaceSpace: refinement is nested only");
  if (static_cast<int>(vertices.size()) != coarse.num_vertices())
    throw std::invalid_argument("G14SurfaceSpace: one position per vertex is required");
  QuadTopology topology = coarse;
  gluing_ = symmetric_gluing(topology, options.blending);
  surface_ = fit_surface(topology, gluing_, vertices, options.degree, options.regularity, onto);
  if (options.level > 0) {
    // Subdivide the level-0 surface exactly (x, y through one FaceGeometry, z through another)
    // and inherit the gluing, level by level; the basis is built on the finest level only.
    const SplitBSpline& b = surface_.basis.bspline;
    FaceGeometry xy, z;
    for (const auto& c : surface_.coefficients) {
      xy.x.push_back(c[0]);
      xy.y.push_back(c[1]);
      z.x.push_back(c[2]);
      z.y.push_back(Eigen::VectorXd::Zero(c[2].size()));
    }
    for (int l = 0; l < options.level; ++l) {
      QuadTopology fine = topology.refined();
      gluing_ = inherited_gluing(topology, gluing_, fine);
      xy = subdivide_geometry(b, xy);
      z = subdivide_geometry(b, z);
      topology = std::move(fine);
    }
    surface_.basis = build_g14_basis(topology, gluing_, options.degree, options.regularity);
    surface_.coefficients.clear();
    for (std::size_t f = 0; f < xy.x.size(); ++f) surface_.coefficients.push_back({xy.x[f], xy.y[f], z.x[f]});
  }
  topology_ = std::make_shared<const QuadTopology>(std::move(topology));

  fold_bound_ = 1e300;
  for (int f = 0; f < topology_->num_faces(); ++f) {
    fold_bound_ = std::min(fold_bound_, face_fold_bound(surface_, f));
    std::vector<Eigen::Vector3d> pts;
    for (int j = 0; j < 4; ++j)
      for (int s = 0; s < 4; ++s) {
        const Point2 uv = reference_edge_point(CellShape::quadrilateral, j, s / 4.0);
        pts.push_back(face_map_jet(surface_, f, uv.x(), uv.y())[0]);
      }
    for (const auto& p : pts)
      for (const auto& r : pts) mesh_size_ = std::max(mesh_size_, (p - r).norm());
  }
  // The same margin as the planar check: a zero of the Jacobian leaves coefficients at round-off.
  if (fold_bound_ <= 1e-8)
    throw InputError("g1_4split surface of '" + coarse.name() +
                     "': a face of the fitted surface is not certified regular (its projection onto the tangent "
                     "plane at the face centre folds or degenerates); the mesh does not fit the symmetric gluing");
  normal_jump_ = surface_normal_jump(*topology_, surface_, 4 * options.degree + 8);
  min_metric_ratio_ = surface_regularity(surface_, 24);
  SpaceFacts facts;
  facts.type = "g1_4split";
  facts.parameters = make_parameters();
  facts.dimension = surface_.basis.dimension();
  facts.num_elements = topology_->num_faces();
  facts.cell_shapes = {CellShape::quadrilateral};
  facts.mesh_size = mesh_size_;
  facts.degree = options_.degree;
  facts.continuity = 1;
  facts.ambient_dimension = 3;
  facts.gradient_jump_samples = 4 * options_.degree + 8;  // surface gradient jump
  for (int e = 0; e < topology_->num_edges(); ++e)
    if (topology_->edge(e).boundary())
      facts.all_boundary_edges.push_back({topology_->edge(e).sides[0].face, topology_->edge(e).sides[0].local_edge});
  set_facts(std::move(facts));
}

std::unique_ptr<Space::Evaluator> G14SurfaceSpace::make_evaluator() const {
  return std::make_unique<ExtractedEvaluator<Core>>(*this, Core{surface_});
}

std::vector<std::pair<std::string, std::string>> G14SurfaceSpace::make_parameters() const {
  const auto sci = [](double x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3e", x);
    return std::string(buf);
  };
  std::vector<std::pair<std::string, std::string>> out = {{"degree", std::to_string(options_.degree)},
          {"regularity", std::to_string(options_.regularity)},
          {"blending", blending_name(options_.blending)},
          {"refinement", "nested"},
          {"faces", std::to_string(topology_->num_faces())},
          {"domain", topology_->name()},
          {"surface_normal_jump", sci(normal_jump_)},
          {"surface_min_metric_ratio", sci(min_metric_ratio_)},
          {"surface_fold_bound", sci(fold_bound_)}};
  if (!onto_name_.empty()) out.emplace_back("fit_onto", onto_name_);
  return out;
}

}  // namespace iga
