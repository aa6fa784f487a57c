// The Bernstein control-point file of a surface (output/bernstein_patches.hpp, format in
// docs/spaces/surface.md): written by a run, read back, and evaluated on its own with the
// formula of the format (F(t) = Σ b_α D!/α! t^α) it reproduces the surface exactly; neighbouring
// patches agree along their shared edges; malformed files name the line.

#include "output/bernstein_patches.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "config/errors.hpp"
#include "geometry/builtin_surface_meshes.hpp"
#include "geometry/rsd/rsd_surface.hpp"
#include "output/surface_files.hpp"
#include "tests/support/input_error.hpp"
#include "tests/support/scratch_files.hpp"

namespace iga {
namespace {

double factorial(int n) { return n <= 1 ? 1.0 : n * factorial(n - 1); }

/// The format's own formula, written out independently of BezierTriangle.
Eigen::Vector3d evaluate_as_documented(const BezierTriangle& patch, const Eigen::Vector3d& t) {
  const int D = patch.degree;
  Eigen::Vector3d x = Eigen::Vector3d::Zero();
  int index = 0;
  for (int a1 = D; a1 >= 0; --a1)
    for (int a2 = D - a1; a2 >= 0; --a2, ++index) {
      const int a3 = D - a1 - a2;
      const double b = factorial(D) / (factorial(a1) * factorial(a2) * factorial(a3)) * std::pow(t[0], a1) *
                       std::pow(t[1], a2) * std::pow(t[2], a3);
      x += b * patch.control[index];
    }
  return x;
}

TEST(BernsteinPatches, AWrittenFileReadBackReproducesTheSurface) {
  const rsd::RsdSurface s = rsd::build_rsd_surface(perturbed_octahedron(), {});
  const SurfacePatches original = surface_patches_of(s);
  const auto names = write_surface_files(original, test::scratch_folder().string(), "octa", 2);
  ASSERT_EQ(names.size(), 2u);
  EXPECT_EQ(names[1], "octa_patches.txt");
  std::ifstream file(test::scratch_folder() / names[1]);
  const SurfacePatches back = read_bernstein_patches(file, names[1]);
  ASSERT_EQ(back.patches.size(), 8u);
  for (std::size_t n = 0; n < back.patches.size(); ++n) {
    EXPECT_EQ(back.patches[n].degree, 8);
    EXPECT_EQ(back.vertices[n], s.mesh.triangles[n]);
    for (const Eigen::Vector3d t : {Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0.2, 0.3, 0.5),
                                    Eigen::Vector3d(1.0 / 3, 1.0 / 3, 1.0 / 3), Eigen::Vector3d(0, 0.7, 0.3)}) {
      const Eigen::Vector3d expected = s.patches[n].value(t);
      EXPECT_LT((evaluate_as_documented(back.patches[n], t) - expected).norm(), 1e-14 * (1 + expected.norm()));
    }
    // Vertex control points are the interpolated mesh points.
    for (int a = 0; a < 3; ++a) {
      const int corner = bezier_index(8, a == 0 ? 8 : 0, a == 1 ? 8 : 0);
      EXPECT_EQ(back.patches[n].control[corner], s.patches[n].control[corner]);
      EXPECT_LT((back.patches[n].control[corner] - s.mesh.points[back.vertices[n][a]]).norm(), 1e-14);
    }
  }
  // Shared edges: the two patches of every interior edge give the same points at equal λ_i; the
  // octahedron is closed, so that is all of its 12 edges.
  int shared = 0;
  for (const SurfaceEdge& e : s.edges) {
    if (!e.interior()) continue;
    ++shared;
    for (double lambda : {0.1, 0.5, 0.8}) {
      Eigen::Vector3d t = Eigen::Vector3d::Zero(), tbar = Eigen::Vector3d::Zero();
      for (int a = 0; a < 3; ++a) {
        if (back.vertices[e.n][a] == e.i) t[a] = lambda;
        if (back.vertices[e.n][a] == e.j) t[a] = 1 - lambda;
        if (back.vertices[e.nbar][a] == e.i) tbar[a] = lambda;
        if (back.vertices[e.nbar][a] == e.j) tbar[a] = 1 - lambda;
      }
      EXPECT_LT((evaluate_as_documented(back.patches[e.n], t) - evaluate_as_documented(back.patches[e.nbar], tbar)).norm(),
                1e-13);
    }
  }
  EXPECT_EQ(shared, 12);
}

TEST(BernsteinPatches, RoundTripIsBitExact) {
  const rsd::RsdSurface s = rsd::build_rsd_surface(height_field(), {rsd::RsdTuple::pi1, rsd::RsdMethod::hermite});
  std::stringstream file;
  write_bernstein_patches(file, surface_patches_of(s), "height field, pi1");
  const SurfacePatches back = read_bernstein_patches(file, "patches.txt");
  ASSERT_EQ(back.patches.size(), s.patches.size());
  for (std::size_t n = 0; n < s.patches.size(); ++n) {
    EXPECT_EQ(back.patches[n].degree, 9);
    for (std::size_t c = 0; c < s.patches[n].control.size(); ++c)
      EXPECT_EQ(back.patches[n].control[c], s.patches[n].control[c]);
  }
}

TEST(BernsteinPatches, MalformedFilesNameTheLine) {
  std::istringstream short_file("iga-run-bezier-triangles 1\ndegree 1\npatches 1\npatch 0 0 1 2\n0 0 0\n1 0 x\n");
  const std::string message = test::input_error([&] { read_bernstein_patches(short_file, "p.txt"); });
  EXPECT_NE(message.find("p.txt:6: expected a control point"), std::string::npos) << message;
  std::istringstream wrong_header("iga-run-bezier-triangles 2\n");
  EXPECT_NE(test::input_error([&] { read_bernstein_patches(wrong_header, "q.txt"); }).find("q.txt:1"),
            std::string::npos);
}

}  // namespace
}  // namespace iga
