#pragma once
/// @file
/// Quality measures of an RSD surface: G1 residual, fold indicator and regularity along the
/// double edges, and the interpolation residual at the vertices (filled into RsdReport).

#include "geometry/rsd/rsd_surface.hpp"

namespace iga::rsd {

/// Cross-derivatives of both patches at parameter t (t = λ_i) of double edge `e`.
struct EdgeFrame {
  Eigen::Vector3d V, Vbar, E;
};
EdgeFrame edge_frame(const RsdSurface& surface, const SurfaceEdge& e, double t);

/// G1 residual, fold α and regularity at one edge point (the definitions of RsdReport).
double g1_residual(const EdgeFrame& frame);
double fold_alpha(const EdgeFrame& frame);
double regularity(const EdgeFrame& frame);

/// Fills the edge and interpolation entries of surface.report.
void measure_surface(RsdSurface& surface);

}  // namespace iga::rsd
