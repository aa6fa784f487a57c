// Multipatch quad meshes for G1 spaces: topology, validation, refinement, geometry-derived gluing.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>

#include "config/errors.hpp"
#include "spaces/g1/gluing_data.hpp"
#include "spaces/g1/multipatch_domains.hpp"

using namespace iga;

namespace {

struct Counts {
  int interior_edges = 0, boundary_edges = 0, interior_vertices = 0;
};

Counts count(const PatchMesh& m) {
  Counts c;
  for (int e = 0; e < m.num_edges(); ++e) (m.edge(e).boundary() ? c.boundary_edges : c.interior_edges)++;
  for (int v = 0; v < m.num_vertices(); ++v) c.interior_vertices += m.fan(v).boundary ? 0 : 1;
  return c;
}

int vertex_at(const PatchMesh& m, Point2 p) {
  for (int v = 0; v < m.num_vertices(); ++v)
    if ((m.vertex(v) - p).norm() < 1e-12) return v;
  return -1;
}

double total_area(const PatchMesh& m) {
  double a = 0;
  for (int f = 0; f < m.num_faces(); ++f)
    for (double u : {0.2113248654051871, 0.7886751345948129})
      for (double v : {0.2113248654051871, 0.7886751345948129}) a += 0.25 * m.map(f, Point2(u, v)).jacobian.determinant();
  return a;
}

}  // namespace

TEST(G1Mesh, ThreePatchSquareTopology) {
  const PatchMesh m = multipatch_domain("3p_square");
  EXPECT_EQ(m.num_faces(), 3);
  EXPECT_EQ(m.num_vertices(), 7);
  EXPECT_EQ(m.num_edges(), 9);
  const Counts c = count(m);
  EXPECT_EQ(c.interior_edges, 3);
  EXPECT_EQ(c.boundary_edges, 6);
  EXPECT_EQ(c.interior_vertices, 1);
  const int centre = vertex_at(m, Point2(0.6, 0.6));
  ASSERT_GE(centre, 0);
  EXPECT_FALSE(m.fan(centre).boundary);
  EXPECT_EQ(m.fan(centre).valence(), 3);
  // A boundary vertex where an interface ends: 2 faces, 3 edges.
  const int side = vertex_at(m, Point2(1.0, 0.7));
  ASSERT_GE(side, 0);
  EXPECT_TRUE(m.fan(side).boundary);
  EXPECT_EQ(m.fan(side).face.size(), 2u);
  EXPECT_EQ(m.fan(side).valence(), 3);
  EXPECT_NEAR(total_area(m), 1.0, 1e-14);
}

TEST(G1Mesh, FivePatchSquareAndPentagonTopology) {
  const PatchMesh s = multipatch_domain("5p_square");
  EXPECT_EQ(s.num_faces(), 5);
  EXPECT_EQ(s.num_vertices(), 8);
  EXPECT_EQ(count(s).interior_edges, 8);
  EXPECT_EQ(count(s).boundary_edges, 4);
  EXPECT_EQ(count(s).interior_vertices, 4);
  for (Point2 p : {Point2(0.2, 0.2), Point2(0.8, 0.2), Point2(0.8, 0.8), Point2(0.2, 0.8)})
    EXPECT_EQ(s.fan(vertex_at(s, p)).valence(), 3);
  EXPECT_NEAR(total_area(s), 1.0, 1e-14);

  const PatchMesh p = multipatch_domain("pentagon");
  EXPECT_EQ(p.num_faces(), 5);
  EXPECT_EQ(p.num_vertices(), 11);
  EXPECT_EQ(count(p).interior_edges, 5);
  EXPECT_EQ(count(p).boundary_edges, 10);
  const int o = vertex_at(p, Point2(0.07, -0.04));
  ASSERT_GE(o, 0);
  EXPECT_EQ(p.fan(o).valence(), 5);
  // Regular pentagon of circumradius 1: area (5/2) sin 72°.
  EXPECT_NEAR(total_area(p), 2.5 * std::sin(2 * std::acos(-1.0) / 5), 1e-13);
}

TEST(G1Mesh, RefinementSplitsEachPatchIntoFourWithTheSameGeometry) {
  const PatchMesh m = multipatch_domain("3p_square");
  const PatchMesh r = m.refined();
  EXPECT_EQ(r.num_faces(), 12);
  EXPECT_EQ(r.num_vertices(), 19);
  EXPECT_EQ(r.num_edges(), 30);
  EXPECT_EQ(count(r).interior_vertices, 1 + 3 + 3);  // old centre, 3 patch centres, 3 interface midpoints
  // Child 2 of patch 0 has corners at parent (0.5,0.5) -> (1,1): its map at (0.5,0.5) is the
  // parent's at (0.75,0.75).
  EXPECT_LT((r.map(2, Point2(0.5, 0.5)).x - m.map(0, Point2(0.75, 0.75)).x).norm(), 1e-15);
  EXPECT_NEAR(total_area(r.refined()), 1.0, 1e-13);
}

TEST(G1Mesh, FansWalkTheirFacesAndEdgesCounterclockwise) {
  // The fans are views into flat arrays: each names, in order, faces that do have the vertex at
  // the named corner, the edge along that corner's u-axis, the next face across the previous local
  // edge, and one more edge when the fan is open; every corner of every face is in exactly one fan.
  for (const char* name : {"3p_square", "5p_pentagon", "lshape_8p", "2q2t_square", "4t_star"}) {
    for (const PatchMesh& m : {multipatch_domain(name), multipatch_domain(name).refined().refined()}) {
      int corners = 0, seen = 0;
      for (int f = 0; f < m.num_faces(); ++f) corners += static_cast<int>(m.face(f).size());
      for (int v = 0; v < m.num_vertices(); ++v) {
        const VertexFan fan = m.fan(v);
        const int n = static_cast<int>(fan.face.size());
        ASSERT_EQ(fan.corner.size(), fan.face.size());
        ASSERT_EQ(fan.valence(), n + (fan.boundary ? 1 : 0)) << name << " vertex " << v;
        seen += n;
        for (int i = 0; i < n; ++i) {
          const int f = fan.face[i], c = fan.corner[i], corners_f = m.num_corners(f);
          EXPECT_EQ(m.face(f)[c], v);
          EXPECT_EQ(fan.edge[i], m.face_edge(f, c));
          const int previous = m.face_edge(f, (c + corners_f - 1) % corners_f);
          if (i + 1 < n) EXPECT_EQ(fan.edge[i + 1], previous) << name << " vertex " << v;
          else EXPECT_EQ(fan.boundary ? fan.edge[n] : fan.edge[0], previous) << name << " vertex " << v;
        }
        if (fan.boundary) {
          EXPECT_TRUE(m.edge(fan.edge.front()).boundary());
          EXPECT_TRUE(m.edge(fan.edge.back()).boundary());
        }
        for (int e : fan.edge) EXPECT_EQ(m.find_edge(m.edge(e).x, m.edge(e).y), e);
      }
      EXPECT_EQ(seen, corners) << name;
    }
  }
}

TEST(G1Mesh, RejectsInvalidMeshesNamingThePatch) {
  const std::vector<Point2> v{{0, 0}, {1, 0}, {1, 1}, {0, 1}, {2, 0}, {2, 1}};
  // Clockwise patch.
  try {
    PatchMesh({v[0], v[1], v[2], v[3]}, {{0, 3, 2, 1}}, "cw");
    FAIL() << "clockwise patch accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("patch 0 is inverted"), std::string::npos) << e.what();
  }
  // Folded (non-convex) patch: the 4th corner pulled inside.
  try {
    PatchMesh({{0, 0}, {1, 0}, {1, 1}, {0.8, 0.2}}, {{0, 1, 2, 3}}, "fold");
    FAIL() << "folded patch accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("patch 0 is folded"), std::string::npos) << e.what();
  }
  // Three patches on the edge between vertices 1 and 2.
  try {
    std::vector<Point2> w = v;
    w.push_back({1.5, 0.2});
    w.push_back({1.5, 0.8});
    PatchMesh(w, {{0, 1, 2, 3}, {1, 4, 5, 2}, {2, 1, 6, 7}}, "three");
    FAIL() << "overlapping patches accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("non-manifold edge between vertices 1 and 2 is shared by patches 0 1 2"), std::string::npos) << e.what();
  }
  try {
    PatchMesh({{0, 0}, {1, 0}, {1, 1}, {0, 1}, {-0.5, 1}, {2, 2}}, {{0, 1, 2, 3}, {0, 1, 5, 4}}, "same-direction");
    FAIL() << "inconsistent orientation accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("patch 1 and patch 0 traverse their shared edge in the same direction"),
              std::string::npos)
        << e.what();
  }
}

TEST(G1Gluing, CompatibleAtEveryInteriorVertex) {
  for (const std::string& name : multipatch_domain_names())
    for (int level = 0; level <= 1; ++level) {
      PatchMesh m = multipatch_domain(name);
      if (level) m = m.refined();
      const std::vector<EdgeGluing> g = gluing_from_geometry(m);
      int checked = 0;
      for (int v = 0; v < m.num_vertices(); ++v) {
        if (m.fan(v).boundary) continue;
        const Eigen::Matrix2d p = vertex_jet_product(m, g, v);
        EXPECT_LT((p - Eigen::Matrix2d::Identity()).cwiseAbs().maxCoeff(), 1e-12) << name << " vertex " << v;
        ++checked;
      }
      EXPECT_GT(checked, 0);
      for (int e = 0; e < m.num_edges(); ++e) {
        if (m.edge(e).boundary()) continue;
        for (double t : {0.0, 0.5, 1.0}) EXPECT_LT(eval_poly(g[e].b, t) / eval_poly(g[e].c, t), 0.0);
      }
    }
}

TEST(G1Gluing, DegreesAndCrossingsOfBilinearEdges) {
  const PatchMesh m = multipatch_domain("3p_square");
  const std::vector<EdgeGluing> g = gluing_from_geometry(m);
  const int centre = vertex_at(m, Point2(0.6, 0.6));
  for (int e = 0; e < m.num_edges(); ++e) {
    if (m.edge(e).boundary()) continue;
    // Generic bilinear quad-quad data: deg a = 2, deg b = deg c = 1 (n = 2), d_τ(k) = 2k (§5).
    EXPECT_GT(std::abs(g[e].a[2]), 1e-3);
    EXPECT_EQ(syzygy_dimension(g[e], 5), 10);
    EXPECT_EQ(syzygy_dimension(g[e], 6), 12);
    EXPECT_FALSE(crossing_at(m, g, e, centre));
  }
  // After refinement, the new edges inside a patch are parametric C1: a = 0, crossing at both ends,
  // d_τ(k) = 2k + 1.
  const PatchMesh r = m.refined();
  const std::vector<EdgeGluing> gr = gluing_from_geometry(r);
  int parametric = 0;
  for (int e = 0; e < r.num_edges(); ++e) {
    if (r.edge(e).boundary()) continue;
    if (gr[e].a.cwiseAbs().maxCoeff() < 1e-13) {
      ++parametric;
      EXPECT_TRUE(gr[e].crossing_x && gr[e].crossing_y);
      EXPECT_EQ(syzygy_dimension(gr[e], 5), 11);
    }
  }
  EXPECT_EQ(parametric, 12);  // 4 inner edges per patch
}

TEST(G1Mesh, BenchmarkDomainsFromTheAnchors) {
  // 5p_pentagon: valence 5 at the origin; area of the regular pentagon with apothem a.
  const PatchMesh p = multipatch_domain("5p_pentagon");
  EXPECT_EQ(p.fan(vertex_at(p, Point2(0, 0))).valence(), 5);
  EXPECT_EQ(count(p).interior_vertices, 1);
  EXPECT_NEAR(total_area(p), 5 * 0.6881909602355869 * 0.5, 1e-12);
  // 3p_hexagon: valence 3 at the origin, regular hexagon of circumradius 1.
  const PatchMesh h = multipatch_domain("3p_hexagon");
  EXPECT_EQ(h.fan(vertex_at(h, Point2(0, 0))).valence(), 3);
  EXPECT_NEAR(total_area(h), 1.5 * std::sqrt(3.0), 1e-12);
  for (int f = 0; f < 3; ++f) EXPECT_TRUE(h.is_affine(f));
  // lshape_8p: (-1,1)^2 minus the fourth quadrant; the re-entrant corner (0,0) is a boundary vertex.
  const PatchMesh l = multipatch_domain("lshape_8p");
  EXPECT_EQ(l.num_faces(), 8);
  EXPECT_NEAR(total_area(l), 3.0, 1e-13);
  EXPECT_TRUE(l.fan(vertex_at(l, Point2(0, 0))).boundary);
  EXPECT_EQ(l.num_vertices(), 12);
  EXPECT_EQ(count(l).interior_vertices, 6);  // the 6 boundary vertices are the corners of the L
}
