#pragma once
/// @file
/// The limits: section applied to a study: the degree and element count the config asks for
/// before the coarsest space is built, every level's estimated size before the study starts (from
/// the coarsest space) and each level's actual size before it is assembled.

#include <string>

#include "config/config_node.hpp"
#include "config/resource_limits.hpp"
#include "spaces/space.hpp"

namespace iga {

/// Size of one level: what memory grows with.
struct SpaceSize {
  double elements = 0;
  double dofs = 0;
  double element_entries = 0;  ///< Σ over elements of (active functions)²: bounds the matrix nonzeros
};

/// Exact size of a built space (one pass over the elements' active functions).
SpaceSize measure(const Space& space);

/// Size of uniform level `level` estimated from level 0: elements, DOFs and entries grow at most
/// fourfold per level in 2D.
SpaceSize uniform_estimate(const SpaceSize& level0, int level);

/// Bytes a level of this size needs, matrix and Cholesky factor included: 8.5 bytes per element
/// entry and log2(dofs) (nested dissection's fill grows like N log N). Calibrated on a B-spline
/// study (264 196 DOFs, quadratic: 2.4 GB measured, 3.2 GB estimated); an estimate, not a bound.
double estimated_memory_bytes(const SpaceSize& size);

/// Before the coarsest space is built: `space.degree` (a number or a list) against
/// limits.max_degree and the elements `space.elements` asks for (a count per direction, or one for
/// both) against limits.max_elements. InputError at the key otherwise.
void check_space_request(const ConfigNode& space, const ResourceLimits& limits);

/// InputError at `node` when `size` exceeds limits.max_elements, max_dofs or max_memory_gb; `what`
/// says which level ("level 3 (estimated from level 0)").
void check_size(const SpaceSize& size, const ResourceLimits& limits, const ConfigNode& node, const std::string& what);

}  // namespace iga
