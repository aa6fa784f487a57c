#pragma once
/// @file
/// PLplot colour-map-0 indices the plots share: 0 the background, 1 axes and text; the series'
/// colours follow.
namespace iga {
inline constexpr int kPlotBackground = 0, kPlotInk = 1;
}  // namespace iga
