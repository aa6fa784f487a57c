// Closed quad meshes as G1 surfaces: the cube and the Catmull–Clark split tetrahedron, each
// coordinate of the bilinear surface projected onto the 4-split space. The tangent planes agree
// across every edge (normal jump at round-off) and the map stays regular.
#include <gtest/gtest.h>

#include "spaces/g1_4split/g1_4split_surface.hpp"

namespace iga {
namespace {

TEST(G14Surface, CubeAndSplitTetrahedronAreSmoothClosedSurfaces) {
  struct Case {
    QuadTopology topology;
    std::vector<Eigen::Vector3d> vertices;
    int k, dimension;
  };
  const Case cases[] = {{cube_topology(), cube_vertices(), 4, 192},
                        {cube_topology(), cube_vertices(), 5, 0},
                        {split_tetrahedron_topology(), split_tetrahedron_vertices(), 4, 360}};
  for (const Case& c : cases) {
    const G14Surface s = fit_surface(c.topology, c.vertices, c.k, Blending::q1);
    if (c.dimension > 0) EXPECT_EQ(s.basis.dimension(), c.dimension);
    const double jump = surface_normal_jump(c.topology, s, 4 * c.k + 8);
    const double regular = surface_regularity(s, 24);
    std::printf("%s k=%d: dim %d, normal jump %.2e, min/max |x_u x x_v| %.3f\n", c.topology.name().c_str(), c.k,
                s.basis.dimension(), jump, regular);
    EXPECT_LT(jump, 1e-10) << c.topology.name();
    EXPECT_GT(regular, 0.05) << c.topology.name();
  }
}

}  // namespace
}  // namespace iga
