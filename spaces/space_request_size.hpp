#pragma once
/// @file
/// The size of a space estimated from its request, before anything is built: for spaces whose
/// building alone may take long or much memory, so that the resource limits refuse them at once.

#include <optional>
#include <string>

#include "config/config_node.hpp"

namespace iga {

struct SpaceRequestSize {
  double elements = 0;
  double dofs = 0;
  double element_entries = 0;  ///< Σ over elements of (active functions)²
  double build_bytes = 0;      ///< memory the space itself takes while it is built
  std::string basis;           ///< what the estimate follows from, for messages
  std::optional<ConfigNode> blame;  ///< the key a level-0 refusal names (the mesh file)
};

}  // namespace iga
