#pragma once
/// @file
/// Dörfler (bulk) marking for adaptive refinement.

#include <vector>

namespace iga {

/// A smallest set M of elements with Σ_{K∈M} η_K² ≥ θ Σ_K η_K², taken in decreasing η_K (ties by
/// element number). θ in (0, 1]; returns element numbers in increasing order. All η zero: empty.
std::vector<int> dorfler_marking(const std::vector<double>& eta, double theta);

}  // namespace iga
