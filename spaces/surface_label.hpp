#pragma once
/// @file
/// A word of the construction report of the surface a space lives on (SurfacePatches::labels:
/// `construction` rsd, `tuple` pi0 or pi1, `method` hermite, paper or none), for the layers above
/// spaces/ that must not include geometry/: which surfaces a form is valid on.

#include <string>

#include "spaces/space.hpp"

namespace iga {

/// The label `key` of the space's surface report; empty when the space has no such surface or the
/// report no such label.
std::string surface_label(const Space& space, const std::string& key);

}  // namespace iga
