// Geometric checks of quad surface files: repeated faces, coincident vertices, degenerate and
// folded faces and non-manifold edges are named with the file line of the face, at any scale;
// the cube and a non-planar (twisted) quad pass.

#include "mesh/validate_quad_surface.hpp"

#include <gtest/gtest.h>

#include <string>

#include "config/errors.hpp"

namespace iga {
namespace {

using V = Eigen::Vector3d;

QuadSurfaceFile cube(double scale = 1.0) {
  QuadSurfaceFile m;
  m.source = "cube.off";
  for (int k = 0; k < 8; ++k) m.points.push_back(scale * V(k & 1, (k >> 1) & 1, (k >> 2) & 1));
  m.quads = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (int f = 0; f < 6; ++f) m.quad_lines.push_back(11 + f);
  return m;
}

std::string error_of(const QuadSurfaceFile& m) {
  try {
    validate_quad_surface(m);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ValidateQuadSurface, TheCubePassesAtAnyScale) {
  for (double scale : {1.0, 1e-6, 1e6}) EXPECT_EQ(error_of(cube(scale)), "") << scale;
  QuadSurfaceFile twisted = cube();
  twisted.points[3] = V(1, 1, 0.3);  // face 1 no longer planar, still a valid bilinear face
  EXPECT_EQ(error_of(twisted), "");
}

TEST(ValidateQuadSurface, RepeatedFacesEitherWayRound) {
  QuadSurfaceFile m = cube();
  m.quads.push_back({1, 3, 2, 0});
  m.quad_lines.push_back(17);
  EXPECT_EQ(error_of(m), "cube.off: face 7 (line 17) repeats face 1 (line 11) (the same four vertices)");
}

TEST(ValidateQuadSurface, CoincidentVerticesAreNamed) {
  for (double scale : {1.0, 1e-6}) {
    QuadSurfaceFile m = cube(scale);
    m.points[7] = m.points[6];
    EXPECT_EQ(error_of(m).rfind("cube.off: vertices 7 and 8 coincide at (0, ", 0), 0u) << error_of(m);
  }
}

TEST(ValidateQuadSurface, DegenerateAndFoldedFaces) {
  QuadSurfaceFile m = cube();
  m.points[3] = V(0.5, 0.5, 0);  // on the diagonal of face 1: a corner of 180 degrees
  EXPECT_EQ(error_of(m), "cube.off: face 1 (line 11) is folded or not convex at corner (0.5, 0.5, 0) (vertex 4)");
  m.points[3] = V(0.2, 0.2, 0);  // past it: an arrowhead
  EXPECT_NE(error_of(m).find("face 1 (line 11) is folded or not convex"), std::string::npos) << error_of(m);
  QuadSurfaceFile flat = cube();
  flat.points[2] = V(0.5, 0, 0);  // face 1 collapses onto the x axis: no area
  flat.points[3] = V(0.7, 0, 0);
  EXPECT_NE(error_of(flat).find("face 1 (line 11) is degenerate (area 0"), std::string::npos) << error_of(flat);
}

TEST(ValidateQuadSurface, AnEdgeOfThreeFaces) {
  QuadSurfaceFile m = cube();
  m.points.push_back(V(0.5, 0.5, -1));
  m.points.push_back(V(0.5, -0.5, -1));
  m.quads.push_back({0, 1, 9, 8});  // a fin on the edge of vertices 1 and 2
  m.quad_lines.push_back(19);
  EXPECT_EQ(error_of(m),
            "cube.off: the edge of vertices 1 and 2 is shared by 3 faces (face 1 (line 11), face 3 (line 13), face 7 "
            "(line 19)): the surface is not a manifold");
}

}  // namespace
}  // namespace iga
