// Closed quad meshes as smooth surfaces in 3D through the Space interface: the cube and the split
// tetrahedron fitted in the 4-split space (dimension 24k(k−2) / brute force), tangent planes and
// surface gradients continuous at round-off, certified free of folds, nested levels keeping the
// surface, Laplace–Beltrami at the optimal H1 rate, quad .obj/.off files read like the built-ins,
// the surface written with its normals, and the refusals with their reasons.
#include <gtest/gtest.h>

#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <Eigen/Dense>
#include <cmath>

#include "config/errors.hpp"
#include "output/surface_geometry_vtk.hpp"
#include "solver/solve_problem.hpp"
#include "spaces/g1_4split/g1_4split_surface_space.hpp"
#include "tests/support/input_error.hpp"
#include "tests/support/test_support.hpp"

using namespace iga;

namespace {

std::string yaml(const std::string& domain, const std::string& space) {
  return "problem: {pde: laplace_beltrami, exact: \"x*y + sin(z) + x\"}\ndomain: " + domain +
         "\nspace: {type: g1_4split, " + space + "}\n";
}

std::string error_of(const std::string& text, int level) {
  return test::input_error([&] { test::space_from_yaml(text, level); });
}

const G14SurfaceSpace& as_surface(const SpacePtr& s) { return dynamic_cast<const G14SurfaceSpace&>(*s); }

/// The split tetrahedron written as OFF (0-based) or OBJ (1-based, with /t/n parts to skip).
std::string tetrahedron_text(bool obj) {
  const QuadTopology t = split_tetrahedron_topology();
  const std::vector<Eigen::Vector3d> v = split_tetrahedron_vertices();
  std::string s = obj ? "# split tetrahedron\n" : "OFF\n" + std::to_string(v.size()) + " " + std::to_string(t.num_faces()) + " 0\n";
  char buf[128];
  for (const auto& p : v) {
    std::snprintf(buf, sizeof buf, "%s%.17g %.17g %.17g\n", obj ? "v " : "", p.x(), p.y(), p.z());
    s += buf;
  }
  for (int f = 0; f < t.num_faces(); ++f) {
    const auto& q = t.face(f);
    if (obj)
      std::snprintf(buf, sizeof buf, "f %d/1/1 %d %d//2 %d\n", q[0] + 1, q[1] + 1, q[2] + 1, q[3] + 1);
    else
      std::snprintf(buf, sizeof buf, "4 %d %d %d %d\n", q[0], q[1], q[2], q[3]);
    s += buf;
  }
  return s;
}

}  // namespace

TEST(G14SurfaceSpace, CubeAndTetrahedronAreSmoothRegularSurfaces) {
  struct Case {
    const char* mesh;
    int k, level, dimension;
  };
  // Cube: 24k(k−2) at level 0 (every edge joins two valence-3 vertices, equal gluing values).
  for (const Case c : {Case{"cube", 4, 0, 192}, Case{"cube", 5, 0, 360}, Case{"cube", 5, 1, -1},
                       Case{"split_tetrahedron", 5, 0, -1}}) {
    const SpacePtr s = test::space_from_yaml(
        yaml(std::string("{type: surface, mesh: ") + c.mesh + "}", "degree: " + std::to_string(c.k) + ", blending: q1"),
        c.level);
    const G14SurfaceSpace& g = as_surface(s);
    EXPECT_EQ(s->ambient_dimension(), 3);
    EXPECT_TRUE(s->boundary_edges("all").empty());
    if (c.dimension > 0) {
      EXPECT_EQ(s->dimension(), c.dimension) << c.mesh;
    } else {  // the local basis spans the whole null space of the C0 + G1 rows
      const Eigen::MatrixXd C(global_constraints(g.topology(), symmetric_gluing(g.topology(), Blending::q1),
                                                 g.basis().bspline));
      if (c.level == 0) EXPECT_EQ(s->dimension(), nullspace_dimension(C)) << c.mesh;
    }
    EXPECT_LT(g.normal_jump(), 1e-10) << c.mesh;
    EXPECT_GT(g.fold_bound(), 1e-3) << c.mesh;
    EXPECT_GT(g.min_metric_ratio(), 0.05) << c.mesh;
    // Surface gradients of basis functions are continuous across the edges.
    double worst = 0.0;
    for (int i = 0; i < s->dimension(); i += 7) {
      Eigen::VectorXd e = Eigen::VectorXd::Zero(s->dimension());
      e(i) = 1.0;
      worst = std::max(worst, *s->max_gradient_jump(e));
    }
    EXPECT_LT(worst, 1e-9) << c.mesh;
  }
}

TEST(G14SurfaceSpace, NestedLevelsKeepTheSurface) {
  const std::string text = yaml("{type: surface, mesh: cube}", "degree: 5");
  const SpacePtr coarse_ptr = test::space_from_yaml(text, 0);
  const G14SurfaceSpace& coarse = as_surface(coarse_ptr);
  const SpacePtr fine_ptr = test::space_from_yaml(text, 1);
  const G14SurfaceSpace& fine = as_surface(fine_ptr);
  double worst = 0.0;
  for (int f = 0; f < coarse.num_elements(); ++f)
    for (double u : {0.05, 0.2, 0.45})
      for (double v : {0.1, 0.3, 0.5}) {  // child 0 of face f covers [0, 1/2]² of f
        const auto a = face_map_jet(coarse.surface(), f, u, v)[0];
        const auto b = face_map_jet(fine.surface(), 4 * f, 2 * u, 2 * v)[0];
        worst = std::max(worst, (a - b).norm());
      }
  EXPECT_LT(worst, 1e-13);
}

TEST(G14SurfaceSpace, LaplaceBeltramiOnTheCubeAtTheOptimalRate) {
  const std::string text = yaml("{type: surface, mesh: cube}", "degree: 5");
  const test::Rates r = test::last_rates(text, 4);
  EXPECT_GT(r.h1, 4.7);  // optimal k = 5
  EXPECT_GT(r.l2, 5.5);  // optimal k + 1 = 6
  const SpacePtr s = test::space_from_yaml(text, 1);
  const LevelResult res = solve_problem(*s, test::problem_from_yaml(text), SolverKind::cholmod).result;
  ASSERT_TRUE(res.g1_jump.has_value());
  EXPECT_LT(*res.g1_jump, 1e-9);
}

TEST(G14SurfaceSpace, QuadObjAndOffFilesGiveTheBuiltInSurface) {
  const SpacePtr builtin = test::space_from_yaml(yaml("{type: surface, mesh: split_tetrahedron}", "degree: 5"));
  for (const char* name : {"tetra.off", "tetra.obj"}) {
    const std::string path = test::scratch_file(name, tetrahedron_text(std::string(name).ends_with(".obj")));
    const SpacePtr s = test::space_from_yaml(yaml("{type: surface, file: " + path + "}", "degree: 5"));
    EXPECT_EQ(s->dimension(), builtin->dimension()) << name;
    const auto& a = as_surface(s).surface().coefficients;
    const auto& b = as_surface(builtin).surface().coefficients;
    double worst = 0.0;
    for (std::size_t f = 0; f < a.size(); ++f)
      for (int d = 0; d < 3; ++d) worst = std::max(worst, (a[f][d] - b[f][d]).cwiseAbs().maxCoeff());
    EXPECT_LT(worst, 1e-12) << name;
  }
}

TEST(G14SurfaceSpace, TheSurfaceIsWrittenWithUnitNormals) {
  const SpacePtr s = test::space_from_yaml(yaml("{type: surface, mesh: cube}", "degree: 4"));
  const std::string path = (test::scratch_folder() / "cube_surface.vtu").string();
  write_surface_geometry_vtu(*s, 4, path);
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkUnstructuredGrid* grid = reader->GetOutput();
  ASSERT_NE(grid->GetPointData()->GetNormals(), nullptr);
  EXPECT_EQ(grid->GetNumberOfCells(), 6 * 4 * 4 * 2);
  vtkDataArray* n = grid->GetPointData()->GetNormals();
  // Unit, and outward: the cube's centre is (½, ½, ½).
  for (vtkIdType p = 0; p < n->GetNumberOfTuples(); ++p) {
    double v[3], x[3];
    n->GetTuple(p, v);
    grid->GetPoint(p, x);
    EXPECT_NEAR(std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]), 1.0, 1e-12);
    EXPECT_GT(v[0] * (x[0] - 0.5) + v[1] * (x[1] - 0.5) + v[2] * (x[2] - 0.5), 0.0);
  }
}

TEST(G14SurfaceSpace, RefusalsNameTheKeyAndTheReason) {
  const std::string below = error_of(yaml("{type: surface, mesh: cube}", "degree: 4, blending: q1"), 2);
  EXPECT_NE(below.find("space.degree"), std::string::npos) << below;
  EXPECT_NE(below.find("smallest degree that works is 5"), std::string::npos) << below;
  const std::string rebuild = error_of(yaml("{type: surface, mesh: cube}", "degree: 5, refinement: rebuild"), 1);
  EXPECT_NE(rebuild.find("space.refinement"), std::string::npos) << rebuild;
  EXPECT_NE(rebuild.find("nested"), std::string::npos) << rebuild;
  const std::string both = error_of(yaml("{type: surface, mesh: cube, file: a.off}", "degree: 5"), 0);
  EXPECT_NE(both.find("not both"), std::string::npos) << both;
  const std::string tri_path = test::scratch_file("tri.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  const std::string tri = error_of(yaml("{type: surface, file: " + tri_path + "}", "degree: 5"), 0);
  EXPECT_NE(tri.find("tri.off:6"), std::string::npos) << tri;
  EXPECT_NE(tri.find("space: surface"), std::string::npos) << tri;
}
