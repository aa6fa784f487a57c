#pragma once
// G+Smo's biharmonic_surface_example, shared by the surface tests: u = z on the graph z = x² − y²,
// whose source Δ_Γ²u is this rational function of x and y.

namespace iga::test {

inline constexpr const char* kGismoSurfaceSource =
    "64*(x - y)*(x + y)*(13 + 64*x^4 + 12*y^2 + 64*y^4 + x^2*(12 - 768*y^2))/(1 + 4*x^2 + 4*y^2)^5";

}  // namespace iga::test
