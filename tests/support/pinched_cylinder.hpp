#pragma once
/// @file
/// The pinched cylinder of the shell tests (note §3: R = 300, L = 600, t = 3, E = 3e6, ν = 0.3,
/// rigid diaphragms, two opposite unit loads at mid-length; 1.82488e-5 under each load) as the whole
/// periodic patch: the problem and domain blocks of configs/shell-pinched-cylinder.yaml, for tests
/// that add their own space and output blocks.

namespace iga::test {

inline constexpr const char* kPinchedCylinderProblemAndDomain = R"(
problem:
  pde: kirchhoff_love_shell
  material: {youngs_modulus: 3e6, poisson_ratio: 0.3, thickness: 3}
  point_loads:
    - {point: [300, 0, 300], force: [0, 0, -1]}
    - {point: [300, 0, -300], force: [0, 0, 1]}
  boundary: {bottom: {fixed: [y, z]}, top: {fixed: [y, z]}}
domain: {type: surface_patch, shape: cylinder, radius: 300, length: 600, half_angle: 180})";

}  // namespace iga::test
