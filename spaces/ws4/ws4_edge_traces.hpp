#pragma once
/// @file
/// Universal 1D maps along an edge of a WS4 macro-triangle (notes §2.3, App. B). With the edge
/// e(s) = x_a + s (x_b − x_a), s ∈ [0, 1] (breakpoints ¼, ½, ¾), the traces g_m(s) = ∂_n^m f(e(s))
/// of a WS4 spline f are univariate splines fixed by few data:
///  - m = 0: C³ quartic,   data [g(0), g′(0), g″(0), g‴(0), g(1), g′(1), g″(1), g‴(1)];
///  - m = 1: C² cubic,     data [g(0), g′(0), g″(0), g(1), g′(1), g″(1), g(½)];
///  - m = 2: C¹ quadratic, data [g(0), g′(0), g(1), g′(1), g(¼), g(¾)].
/// The maps give the derivatives g_m^{(j)}(s) at s ∈ {¼, ½, ¾} that the edge functionals of the
/// element need, as coefficients over those data.

#include <array>
#include <vector>

namespace iga::ws4 {

struct EdgeTraceData {
  int end_derivatives;             ///< derivatives 0 … end_derivatives − 1 at s = 0 and at s = 1
  std::vector<double> interior_s;  ///< then the values at these parameters
  int size() const { return 2 * end_derivatives + static_cast<int>(interior_s.size()); }
};

/// The data layout of trace g_m, m = 0, 1, 2.
const EdgeTraceData& edge_trace_data(int m);

/// Coefficients over the data of g_m (m = 0, 1, 2) giving g_m^{(j)}(s); defined for
/// (m, j, s) with j >= 1, m + j <= 3 and s ∈ {¼, ½, ¾} (all that the functionals need).
/// Throws std::logic_error for any other request.
const std::vector<long double>& edge_trace_map(int m, int j, double s);

}  // namespace iga::ws4
