#pragma once
/// @file
/// User-named functionals of the discrete solution, evaluated at every level of a study
/// (`output.functionals`): the value at a point, or the integral of u over the domain. With no
/// exact solution they show convergence through their observed (Richardson) orders. On a surface in
/// 3D a functional is the value at a point of the surface, {point: [x, y, z]}, and for a vector
/// field (a shell's displacement) one of its components, {point: [x, y, z], component: z}.

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "config/config_node.hpp"
#include "spaces/point_location.hpp"
#include "spaces/space.hpp"
#include "solver/formulation.hpp"

namespace iga {

struct FunctionalSpec {
  enum class Kind { point, integral, surface_point };
  std::string name;
  Kind kind = Kind::integral;
  Point2 point = Point2::Zero();            ///< Kind::point
  Eigen::Vector3d point3 = Eigen::Vector3d::Zero();  ///< Kind::surface_point
  int component = 0;                        ///< Kind::surface_point of a vector field: 0, 1, 2 (x, y, z)
};

/// Parse `output.functionals`: a map name -> {point: [x, y]} or {integral: u}; on a surface
/// {point: [x, y, z]}, with `component: x|y|z` when the solution has `components` = 3. Points are
/// located on `coarse` (InputError at the config place when the point is outside the domain).
std::vector<FunctionalSpec> parse_functionals(const ConfigNode& node, const Space& coarse, int components = 1);

/// Value of each functional for u_h = Σ c_i N_i on `space` (a vector field: its components'
/// coefficients in blocks of dimension()). Planar points are located by `locator` (a
/// PointLocator of `space`, made here when null and a functional needs it).
/// A process holding part of the space (rank_part.hpp) gives its `share`: points are taken from
/// the lowest rank whose part holds them, integrals summed over the ranks' own elements.
std::vector<double> evaluate_functionals(const std::vector<FunctionalSpec>& functionals, const Space& space,
                                         const Eigen::VectorXd& coefficients, const PointLocator* locator = nullptr,
                                         const WorkShare& share = {});

/// Observed order of a sequence F_0, F_1, ... on meshes h_0, h_1, ... from three consecutive
/// values (Richardson): log(|F_{l-1} − F_{l-2}| / |F_l − F_{l-1}|) / log(h_{l-1} / h_l); nullopt
/// for l < 2 or when a difference vanishes.
std::optional<double> richardson_order(const std::vector<double>& values, const std::vector<double>& h, std::size_t l);

}  // namespace iga
