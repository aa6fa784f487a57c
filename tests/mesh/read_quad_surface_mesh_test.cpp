// Quad meshes in 3D from .obj and .off (closed quad surfaces): points and quads as written, OBJ
// corner forms i, i/t, i//n, i/t/n and negative indices, and errors that name file and line.
#include <gtest/gtest.h>

#include <sstream>

#include "mesh/read_quad_surface_mesh.hpp"
#include "tests/support/input_error.hpp"

namespace iga {
namespace {

TEST(ReadQuadSurface, ObjAndOffGiveTheSameQuads) {
  std::istringstream obj(
      "# two quads folded along x = 0\nv 0 0 0\nv 0 1 0\nv 1 0 0\nv 1 1 0\nv -1 0 1\nv -1 1 1\nvn 0 0 1\n"
      "f 1/1/1 3 4//1 2\nf -2 1 2 -1\n");
  const QuadSurfaceFile a = read_obj_quad_surface(obj, "a.obj");
  std::istringstream off("OFF\n6 2 0\n0 0 0\n0 1 0\n1 0 0\n1 1 0\n-1 0 1\n-1 1 1\n4 0 2 3 1\n4 4 0 1 5 255 0 0\n");
  const QuadSurfaceFile b = read_off_quad_surface(off, "b.off");
  ASSERT_EQ(a.points.size(), 6u);
  ASSERT_EQ(b.points.size(), 6u);
  EXPECT_EQ(a.points[4], Eigen::Vector3d(-1, 0, 1));
  ASSERT_EQ(a.quads.size(), 2u);
  EXPECT_EQ(a.quads, b.quads);
  EXPECT_EQ(a.quads[0], (std::array<int, 4>{0, 2, 3, 1}));
  EXPECT_EQ(a.quad_lines, (std::vector<int>{9, 10}));
  EXPECT_EQ(b.quad_lines, (std::vector<int>{9, 10}));
}

TEST(ReadQuadSurface, ErrorsNameFileLineAndReason) {
  const auto obj_error = [](const std::string& text) {
    return test::input_error([&] {
      std::istringstream in(text);
      read_obj_quad_surface(in, "s.obj");
    });
  };
  const auto off_error = [](const std::string& text) {
    return test::input_error([&] {
      std::istringstream in(text);
      read_off_quad_surface(in, "s.off");
    });
  };
  EXPECT_NE(obj_error("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").find("s.obj:4: a face with 3 vertices"), std::string::npos);
  EXPECT_NE(obj_error("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").find("space: surface"), std::string::npos);
  EXPECT_NE(obj_error("v 0 0\n").find("s.obj:1"), std::string::npos);
  EXPECT_NE(obj_error("v 0 0 0\nf 1 2 3 4\n").find("s.obj:2"), std::string::npos);
  EXPECT_NE(obj_error("v 0 0 0\n").find("no faces"), std::string::npos);
  EXPECT_NE(obj_error("cube\n").find("unknown OBJ statement"), std::string::npos);
  EXPECT_NE(off_error("OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n").find("s.off:7: a face with 3"),
            std::string::npos);
  EXPECT_NE(off_error("OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 4\n").find("does not exist"), std::string::npos);
  EXPECT_NE(off_error("OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n").find("ends after 1 of 2 faces"),
            std::string::npos);
  EXPECT_NE(test::input_error([] { read_quad_surface_mesh("cube.stl"); }).find("expected .obj or .off"),
            std::string::npos);
}

}  // namespace
}  // namespace iga
