#include "spaces/surface_patch/surface_patch_space.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "config/errors.hpp"
#include "spaces/bspline/bspline_basis_1d.hpp"
#include "spaces/bspline/tensor_bernstein_tables.hpp"
#include "spaces/bspline/patch_geometry.hpp"
#include "spaces/bspline/tensor_bspline_space.hpp"
#include "spaces/extracted_evaluator.hpp"

namespace iga {

/// The explicit core (element_core.hpp): tensor Bernstein basis (local index a + b (p+1)), the
/// stored C_v ⊗ C_u, the jets of the exact map.
struct SurfacePatchSpace::Core {
  using Jet = SurfaceJet;
  static constexpr bool identity = false;
  const SurfacePatchSpace& space;

  int kind(int /*e*/) const { return 0; }
  int tabulate(int /*kind*/, const std::vector<Point2>& points, int /*order*/, LocalTables& t) const {
    return tabulate_tensor_bernstein(space.dir_[0].degree, space.dir_[1].degree, points, t);
  }
  const std::vector<int>& active(int e) const { return space.dofs_[e]; }
  Extraction extraction(int e) const { return extraction_view(space.extraction_[e]); }
  void map(int e, const QuadratureRule& rule, const LocalTables& /*t*/, int order, std::vector<Jet>& jets) const {
    space.element_jets(e, rule, order >= 2, jets);
  }
};

SurfacePatchSpace::SurfacePatchSpace(std::shared_ptr<const NurbsSurfaceMap> map, int p, int r,
                                     std::array<int, 2> elements)
    : map_(std::move(map)) {
  if (!map_) throw std::invalid_argument("SurfacePatchSpace: no map");
  if (p < 1 || r < 0 || r > p - 1) throw std::invalid_argument("SurfacePatchSpace: need p >= 1 and 0 <= r <= p - 1");
  for (int d = 0; d < 2; ++d) {
    const KnotVector& g = map_->knots(d);
    const std::vector<double> gb = g.breakpoints();
    const int spans = g.num_spans();
    if (elements[d] < 1 || elements[d] % spans != 0)
      throw std::invalid_argument(std::to_string(elements[d]) + " elements along " + (d == 0 ? "u" : "v") +
                                  " do not split the " + std::to_string(spans) + " spans of the patch evenly; use a "
                                  "multiple of " + std::to_string(spans));
    const int per = elements[d] / spans;
    std::vector<double> bp{0.0};
    std::vector<int> continuity;
    // The seam (k = 0) of a periodic direction, then every breakpoint: the map's continuity at its own
    // breakpoints, r at the new ones inside a span.
    continuity.push_back(map_->periodic(d) ? std::min(r, map_->measured_continuity(d, 0.0)) : r);
    for (std::size_t k = 0; k + 1 < gb.size(); ++k) {
      for (int i = 1; i < per; ++i) {
        bp.push_back(gb[k] + (gb[k + 1] - gb[k]) * i / per);
        continuity.push_back(r);
      }
      bp.push_back(gb[k + 1]);
      if (k + 2 < gb.size()) continuity.push_back(std::min(r, map_->measured_continuity(d, gb[k + 1])));
    }
    for (int c : continuity)
      if (c < 0)
        throw InputError(map_->description() + ": the map is discontinuous across a knot line in direction " +
                         (d == 0 ? "u" : "v"));
    dir_[d] = make_spline_direction(p, map_->periodic(d), bp, continuity);
    for (int e = 0; e < dir_[d].num_elements(); ++e)
      geometry_span_[d].push_back(g.find_span(0.5 * (dir_[d].element_lo[e] + dir_[d].element_hi[e])));
  }
  const int nex = dir_[0].num_elements(), ney = dir_[1].num_elements(), nu = dir_[0].num_functions;
  for (int ey = 0; ey < ney; ++ey)
    for (int ex = 0; ex < nex; ++ex) {
      std::vector<int> dofs;
      for (int j : dir_[1].active[ey])
        for (int i : dir_[0].active[ex]) dofs.push_back(i + j * nu);
      extraction_.push_back(tensor_extraction(dir_[0].extraction[ex], dir_[1].extraction[ey]));
      dofs_.push_back(std::move(dofs));
    }
  set_facts(make_facts(r));
}

Point2 SurfacePatchSpace::parameter(int e, const Point2& r) const {
  const int ex = e % num_elements_u(), ey = e / num_elements_u();
  return {dir_[0].element_lo[ex] + r.x() * (dir_[0].element_hi[ex] - dir_[0].element_lo[ex]),
          dir_[1].element_lo[ey] + r.y() * (dir_[1].element_hi[ey] - dir_[1].element_lo[ey])};
}

void SurfacePatchSpace::element_jets(int e, const QuadratureRule& rule, bool second,
                                     std::vector<SurfaceJet>& jets) const {
  const int ex = e % num_elements_u(), ey = e / num_elements_u();
  const double hu = dir_[0].element_hi[ex] - dir_[0].element_lo[ex];
  const double hv = dir_[1].element_hi[ey] - dir_[1].element_lo[ey];
  const int su = geometry_span_[0][ex], sv = geometry_span_[1][ey];
  jets.resize(rule.size());
  for (int k = 0; k < rule.size(); ++k) {
    // Chain rule through the affine map reference square → parameter box.
    const auto d = map_->derivatives(parameter(e, rule.points[k]), su, sv);
    Eigen::Matrix<double, 3, 2> J;
    J << hu * d[1][0], hv * d[0][1];
    if (second) {
      const std::array<Eigen::Vector3d, 3> xab{hu * hu * d[2][0], hu * hv * d[1][1], hv * hv * d[0][2]};
      fill_surface_jet(jets[k], d[0][0], J, &xab);
    } else {
      fill_surface_jet(jets[k], d[0][0], J);
    }
  }
}

std::unique_ptr<Space::Evaluator> SurfacePatchSpace::make_evaluator() const {
  return std::make_unique<ExtractedEvaluator<Core>>(*this, Core{*this});
}

std::vector<InteriorEdge> SurfacePatchSpace::interior_edges() const {
  // Reference edges: 0 bottom (t, 0), 1 right (1, t), 2 top (1 − t, 1), 3 left (0, 1 − t); a
  // neighbour's shared edge runs the other way, hence b0 = 1, b1 = 0.
  const int nex = dir_[0].num_elements(), ney = dir_[1].num_elements();
  std::vector<InteriorEdge> edges;
  for (int ey = 0; ey < ney; ++ey)
    for (int ex = 0; ex < nex; ++ex) {
      const int e = ex + ey * nex;
      if (ex + 1 < nex || dir_[0].periodic) edges.push_back({e, 1, 0.0, 1.0, (ex + 1) % nex + ey * nex, 3, 1.0, 0.0});
      if (ey + 1 < ney || dir_[1].periodic) edges.push_back({e, 2, 0.0, 1.0, ex + ((ey + 1) % ney) * nex, 0, 1.0, 0.0});
    }
  return edges;
}

SpaceFacts SurfacePatchSpace::make_facts(int r) const {
  SpaceFacts f;
  f.type = "bspline";
  const int p = dir_[0].degree, nex = dir_[0].num_elements(), ney = dir_[1].num_elements();
  std::string periodic = dir_[0].periodic ? (dir_[1].periodic ? "u, v" : "u") : (dir_[1].periodic ? "v" : "none");
  f.parameters = {{"degree", std::to_string(p)},
                  {"regularity", std::to_string(r)},
                  {"elements", std::to_string(nex) + "x" + std::to_string(ney)},
                  {"domain", map_->description()},
                  {"periodic", periodic}};
  f.dimension = dir_[0].num_functions * dir_[1].num_functions;
  f.num_elements = nex * ney;
  f.cell_shapes = {CellShape::quadrilateral};
  f.degree = p;
  f.continuity = std::min(dir_[0].min_continuity, dir_[1].min_continuity);
  f.affine_elements = false;
  f.ambient_dimension = 3;
  // h: the largest distance between corners and edge midpoints of an element (a chord bound of its diameter).
  const Point2 refs[8] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.5, 0}, {1, 0.5}, {0.5, 1}, {0, 0.5}};
  for (int e = 0; e < nex * ney; ++e) {
    Eigen::Vector3d x[8];
    for (int i = 0; i < 8; ++i) x[i] = map_->point(parameter(e, refs[i]));
    for (int i = 0; i < 8; ++i)
      for (int j = i + 1; j < 8; ++j) f.mesh_size = std::max(f.mesh_size, (x[i] - x[j]).norm());
  }
  add_grid_boundary(f, nex, ney, !dir_[0].periodic, !dir_[1].periodic);
  return f;
}

OpenSurfacePatchSpace::OpenSurfacePatchSpace(std::shared_ptr<const NurbsSurfaceMap> map, int degree, int regularity,
                                             std::array<int, 2> elements)
    : SurfacePatchSpace(std::move(map), degree, regularity, elements) {
  if (direction(0).periodic || direction(1).periodic)
    throw std::logic_error("OpenSurfacePatchSpace: a periodic direction is not the lift of a square");
  planar_ = std::make_shared<const TensorBSplineSpace>(
      std::make_shared<const PatchGeometry>(PatchGeometry::rectangle(Point2(0, 0), Point2(1, 1))),
      KnotVector(degree, direction(0).open_knots), KnotVector(degree, direction(1).open_knots));
  if (planar_->dimension() != dimension() || planar_->num_elements() != num_elements())
    throw std::logic_error("OpenSurfacePatchSpace: the planar space does not match");
}

Eigen::Matrix<double, 3, 2> OpenSurfacePatchSpace::lift_jacobian(const Point2& p) const {
  const auto d = map().derivatives(p, map().knots(0).find_span(p.x()), map().knots(1).find_span(p.y()));
  Eigen::Matrix<double, 3, 2> J;
  J << d[1][0], d[0][1];
  return J;
}

SpacePtr make_surface_patch_space(std::shared_ptr<const NurbsSurfaceMap> map, int degree, int regularity,
                                  std::array<int, 2> elements) {
  if (map->periodic(0) || map->periodic(1))
    return std::make_shared<const SurfacePatchSpace>(std::move(map), degree, regularity, elements);
  return std::make_shared<const OpenSurfacePatchSpace>(std::move(map), degree, regularity, elements);
}

}  // namespace iga
