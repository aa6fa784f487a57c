#include "spaces/surface_orientation.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <utility>

#include "spaces/element_values.hpp"

namespace iga {

namespace {

/// x_ξ × x_η (not normalised) at reference point r of element e.
Eigen::Vector3d raw_normal(Space::Evaluator& evaluator, int e, const Point2& r, PointValues& g) {
  QuadratureRule one;
  one.points = {r};
  one.weights = {0.0};
  evaluator.evaluate_geometry(e, one, g);
  return Eigen::Vector3d(g.jacobian3[0].col(0)).cross(Eigen::Vector3d(g.jacobian3[0].col(1)));
}

}  // namespace

SurfaceOrientation orient_surface(const Space& space, int quad_degree) {
  if (space.ambient_dimension() != 3) throw std::logic_error("orient_surface: the space is not on a surface in 3D");
  const int ne = space.num_elements();
  // Relative signs across interior edges, from the two normals at the middle of each shared piece
  // (a G1 surface: they are equal or opposite).
  std::vector<std::vector<std::pair<int, int>>> neighbours(ne);
  const std::unique_ptr<Space::Evaluator> evaluator = space.make_evaluator();
  PointValues g;
  for (const InteriorEdge& edge : space.interior_edges()) {
    const Point2 ra = reference_edge_point(space.cell_shape(edge.element_a), edge.edge_a, 0.5 * (edge.a0 + edge.a1));
    const Point2 rb = reference_edge_point(space.cell_shape(edge.element_b), edge.edge_b, 0.5 * (edge.b0 + edge.b1));
    const Eigen::Vector3d na = raw_normal(*evaluator, edge.element_a, ra, g);
    const Eigen::Vector3d nb = raw_normal(*evaluator, edge.element_b, rb, g);
    const int relative = na.dot(nb) >= 0 ? 1 : -1;
    neighbours[edge.element_a].emplace_back(edge.element_b, relative);
    neighbours[edge.element_b].emplace_back(edge.element_a, relative);
  }
  SurfaceOrientation out;
  out.sign.assign(ne, 0);
  std::vector<int> piece(ne, -1);
  for (int seed = 0; seed < ne; ++seed) {
    if (out.sign[seed] != 0) continue;
    const int id = out.pieces++;
    std::vector<int> members{seed};
    out.sign[seed] = 1;
    piece[seed] = id;
    for (std::size_t k = 0; k < members.size(); ++k)
      for (const auto& [other, relative] : neighbours[members[k]]) {
        const int wanted = out.sign[members[k]] * relative;
        if (out.sign[other] == 0) {
          out.sign[other] = wanted;
          piece[other] = id;
          members.push_back(other);
        } else if (out.sign[other] != wanted) {
          out.orientable = false;
        }
      }
  }
  // Per piece: area, centroid, then V = ∫ (x − x₀)·n and ∫ n with the propagated signs.
  ElementValues ev(space, update_values | update_surface_curvature);
  std::vector<double> area(out.pieces, 0.0), volume(out.pieces, 0.0), extent(out.pieces, 0.0);
  std::vector<Eigen::Vector3d> centroid(out.pieces, Eigen::Vector3d::Zero()), mean(out.pieces, Eigen::Vector3d::Zero());
  for (int pass = 0; pass < 2; ++pass)
    for (int e = 0; e < ne; ++e) {
      ev.reinit(e, *space.quadrature(e, quad_degree));
      const int p = piece[e];
      for (int k = 0; k < ev.num_points(); ++k) {
        const Eigen::Vector3d x = ev.values().x3.col(k), n = out.sign[e] * ev.values().normal3.col(k);
        const double w = ev.jxw()(k);
        if (pass == 0) {
          area[p] += w;
          centroid[p] += w * x;
        } else {
          volume[p] += w * (x - centroid[p]).dot(n);
          mean[p] += w * n;
          extent[p] = std::max(extent[p], (x - centroid[p]).norm());
        }
      }
      if (pass == 0 && e == ne - 1)
        for (int q = 0; q < out.pieces; ++q) centroid[q] /= area[q];
    }
  std::vector<int> flip(out.pieces, 1);
  for (int p = 0; p < out.pieces; ++p) {
    if (std::abs(volume[p]) > 1e-6 * area[p] * extent[p]) {
      flip[p] = volume[p] > 0 ? 1 : -1;
    } else {
      Eigen::Index i;
      const double largest = mean[p].cwiseAbs().maxCoeff(&i);
      out.flat = true;
      if (largest > 1e-6 * area[p])
        flip[p] = mean[p](i) > 0 ? 1 : -1;
      else
        out.decided = false;
    }
    out.volume += flip[p] * volume[p] / 3.0;
  }
  for (int e = 0; e < ne; ++e) out.sign[e] *= flip[piece[e]];
  return out;
}

}  // namespace iga
