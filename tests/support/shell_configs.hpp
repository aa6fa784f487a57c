#pragma once
// Shell configs shared by tests.

namespace iga::test {

/// The free pinched hemisphere with the 18° hole (MacNeal–Harder): four radial point loads and no
/// boundary condition, so the rigid motions are pinned by the formulation; cubic, 8 × 2 elements.
inline constexpr const char* kFreePinchedHemisphere = R"yaml(
problem:
  pde: kirchhoff_love_shell
  material: {youngs_modulus: 6.825e7, poisson_ratio: 0.3, thickness: 0.04}
  point_loads:
    - {point: [10, 0, 0], force: [2, 0, 0]}
    - {point: [0, 10, 0], force: [0, -2, 0]}
    - {point: [-10, 0, 0], force: [-2, 0, 0]}
    - {point: [0, -10, 0], force: [0, 2, 0]}
domain: {type: surface_patch, shape: sphere, radius: 10, hole: 18, sweep: 360}
space: {type: bspline, degree: 3, elements: [8, 2]}
)yaml";

}  // namespace iga::test
