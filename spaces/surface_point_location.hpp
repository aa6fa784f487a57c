#pragma once
/// @file
/// Where a point of a surface in 3D lies on a surface space: the element and reference
/// coordinates whose image is the point (Gauss–Newton on |X(ξ) − p|² in the reference cell,
/// started from the nearest of a few samples per element). Through the Space interface only, so it
/// works for every surface space (patches, 4-split surfaces, graphs); PointLocator is the planar one.

#include <Eigen/Core>
#include <optional>

#include "spaces/point_location.hpp"
#include "spaces/space.hpp"

namespace iga {

/// The element holding `x` and its reference coordinates, or nullopt when no point of the surface
/// is within `tolerance` of x. On an edge shared by elements, one of them.
std::optional<PointLocation> locate_on_surface(const Space& space, const Eigen::Vector3d& x,
                                               Space::Evaluator& evaluator, double tolerance);

/// The surface's point nearest to `x` among the local minima of |X(ξ) − x| found in the elements
/// closest to x (by samples), and its distance; for points given near, not on, a surface (a shell's
/// point load snapped onto a fitted surface that does not pass through the mesh's vertices).
std::optional<PointLocation> nearest_on_surface(const Space& space, const Eigen::Vector3d& x,
                                                Space::Evaluator& evaluator, double& distance);

}  // namespace iga
