// T-mesh topology, admissibility checks and the dimension formula (21) against the notes' numbers
// and a brute-force null-space count.
#include <gtest/gtest.h>

#include <numbers>

#include "tests/spaces/tmesh/brute_force_dimension.hpp"
#include "spaces/tmesh/tmesh.hpp"

using namespace iga;

namespace {

constexpr double pi = std::numbers::pi;
constexpr std::int64_t U = 1024;  // lattice units per mesh unit (room to refine)

struct Box {
  int x0, x1, y0, y1, section = 0;
};

/// Mesh from boxes in mesh units; one mesh unit is `scale` long.
TMesh mesh_of(const std::vector<Box>& boxes, std::vector<SectionSpec> sections, double scale = 1.0) {
  std::vector<TCell> cells;
  for (const Box& b : boxes) cells.push_back({b.x0 * U, b.x1 * U, b.y0 * U, b.y1 * U, b.section, b.section});
  return TMesh(cells, std::move(sections), {0, 0}, {scale / U, scale / U});
}

SectionSpec trig(int n, double w = 1.0) { return {SectionFamily::trigonometric, n, w}; }
SectionSpec hyp(int n, double w) { return {SectionFamily::hyperbolic, n, w}; }
SectionSpec poly(int n) { return {SectionFamily::polynomial, n, 0.0}; }

// Fig. 7 reconstruction (notes §2.6), units of pi/4: A, B, C, D, E, F1, F2.
std::vector<Box> fig7(int section_a = 0, int section_b = 0) {
  return {{0, 2, 0, 2, section_a}, {0, 2, 2, 3, section_b}, {2, 3, 2, 3}, {0, 3, 3, 4}, {3, 4, 2, 4}, {2, 3, 0, 2}, {3, 4, 0, 2}};
}

// Dyadic hierarchical mesh (notes §7.5 item 2), units of pi/4 halved: size-2 cells are 4 units.
std::vector<Box> dyadic() {
  return {{4, 8, 0, 4}, {0, 4, 4, 8}, {4, 8, 4, 8}, {2, 4, 0, 2}, {0, 2, 0, 2}, {0, 2, 2, 4},
          {2, 3, 2, 3}, {3, 4, 2, 3}, {2, 3, 3, 4}, {3, 4, 3, 4}};
}

int count_edges(const TMesh& m, int d) {
  int k = 0;
  for (const auto& e : m.edges()) k += e.d == d ? 1 : 0;
  return k;
}

}  // namespace

TEST(TmeshMesh, PaperFigure7Spaces) {
  const TMesh s1 = mesh_of(fig7(), {hyp(5, 3.0)}, pi / 4);
  EXPECT_EQ(s1.admissibility_problem(), "");
  EXPECT_EQ(s1.num_non_t_vertices(), 12);
  EXPECT_EQ(int(s1.vertices().size()) - s1.num_non_t_vertices(), 2);
  EXPECT_EQ(s1.edges().size(), 18u);
  EXPECT_EQ(s1.longest_chain(), 2);
  EXPECT_EQ(s1.dimension_formula(1, 1), 148);
  EXPECT_EQ(mesh_of(fig7(), {poly(5)}, pi / 4).dimension_formula(1, 1), 148);
  // S2: trig 1.9 on A, cosh 3 on B, quintic polynomials elsewhere.
  const TMesh s2 = mesh_of(fig7(1, 2), {poly(5), trig(5, 1.9), hyp(5, 3.0)}, pi / 4);
  EXPECT_EQ(count_edges(s2, 0), 4);
  EXPECT_EQ(count_edges(s2, 2), 14);
  EXPECT_EQ(s2.dimension_formula(1, 1), 132);
  EXPECT_EQ(brute_force_dimension(s2, 1, 1), 132);
  EXPECT_EQ(brute_force_dimension(s1, 1, 1), 148);
  // S2 again from S1 with other sections (topology kept, d_e recomputed), and back.
  std::vector<std::array<int, 2>> sections(s1.num_cells(), {0, 0});
  sections[0] = {1, 1};
  sections[1] = {2, 2};
  const TMesh s2_from_s1 = s1.with_sections(sections, {poly(5), trig(5, 1.9), hyp(5, 3.0)});
  EXPECT_EQ(count_edges(s2_from_s1, 0), 4);
  EXPECT_EQ(s2_from_s1.dimension_formula(1, 1), 132);
  const TMesh s1_again = s2_from_s1.with_sections(std::vector<std::array<int, 2>>(s1.num_cells(), {0, 0}), {hyp(5, 3.0)});
  EXPECT_EQ(count_edges(s1_again, 2), 18);
  EXPECT_EQ(s1_again.dimension_formula(1, 1), 148);
  EXPECT_THROW(s1.with_sections(sections, {poly(5)}), std::invalid_argument);
}

TEST(TmeshMesh, Figure7OtherSpaces) {
  auto dim = [](SectionSpec s, int r) { return mesh_of(fig7(), {s}, pi / 4).dimension_formula(r, r); };
  EXPECT_EQ(dim(trig(3), 1), 48);
  EXPECT_EQ(dim(trig(2), 0), 37);
  EXPECT_EQ(dim(trig(3), 0), 76);
  EXPECT_EQ(dim(hyp(4, 1.0), 1), 91);
  EXPECT_EQ(dim(trig(5), 2), 108);
  EXPECT_EQ(dim(trig(7), 3), 192);
  EXPECT_EQ(brute_force_dimension(mesh_of(fig7(), {trig(3)}, pi / 4), 1, 1), 48);
  EXPECT_EQ(brute_force_dimension(mesh_of(fig7(), {trig(2)}, pi / 4), 0, 0), 37);
}

TEST(TmeshMesh, NonConformingLShapeUsesTheCorrectedTJunctionRule) {
  const TMesh m = mesh_of({{0, 2, 0, 1}, {0, 1, 1, 2}}, {trig(3)});
  EXPECT_EQ(m.admissibility_problem(), "");
  EXPECT_EQ(m.num_non_t_vertices(), 6);
  EXPECT_EQ(m.edges().size(), 7u);
  EXPECT_EQ(m.dimension_formula(1, 1), 24);  // not 28 as with "boundary vertices are never T"
  EXPECT_EQ(brute_force_dimension(m, 1, 1), 24);
  const TMesh m5 = mesh_of({{0, 2, 0, 1}, {0, 1, 1, 2}}, {trig(5)});
  EXPECT_EQ(m5.dimension_formula(1, 1), 60);
  const TMesh m2 = mesh_of({{0, 2, 0, 1}, {0, 1, 1, 2}}, {trig(2)});
  EXPECT_EQ(m2.dimension_formula(0, 0), 15);
  EXPECT_EQ(brute_force_dimension(m2, 0, 0), 15);
  // The conforming 3-cell L-shape.
  EXPECT_EQ(mesh_of({{0, 1, 0, 1}, {1, 2, 0, 1}, {0, 1, 1, 2}}, {trig(3)}).dimension_formula(1, 1), 32);
}

TEST(TmeshMesh, RejectsCyclesAndCornerContact) {
  const TMesh pinwheel = mesh_of({{0, 3, 0, 1}, {3, 4, 0, 3}, {1, 4, 3, 4}, {0, 1, 1, 4}, {1, 3, 1, 3}}, {trig(3)});
  EXPECT_NE(pinwheel.admissibility_problem().find("cycle"), std::string::npos);
  EXPECT_EQ(pinwheel.dimension_formula(1, 1), 32);  // notes P3: the formula still matched here
  const TMesh corner = mesh_of({{0, 1, 0, 1}, {1, 2, 1, 2}}, {trig(3)});
  EXPECT_NE(corner.admissibility_problem().find("not regular"), std::string::npos);
  EXPECT_THROW(mesh_of({{0, 2, 0, 2}, {1, 3, 1, 3}}, {trig(3)}), std::invalid_argument);
  // Overlaps the sweep must see: containment, the same cell twice, a cell straddling two others,
  // one starting inside another's x-range; cells that only touch are fine.
  EXPECT_THROW(mesh_of({{0, 4, 0, 4}, {1, 2, 1, 2}}, {trig(3)}), std::invalid_argument);
  EXPECT_THROW(mesh_of({{0, 1, 0, 1}, {0, 1, 0, 1}}, {trig(3)}), std::invalid_argument);
  EXPECT_THROW(mesh_of({{0, 1, 0, 1}, {0, 1, 2, 3}, {0, 1, 1, 3}}, {trig(3)}), std::invalid_argument);
  EXPECT_THROW(mesh_of({{0, 1, 0, 1}, {1, 2, 0, 1}, {0, 3, 3, 4}, {2, 3, 2, 5}}, {trig(3)}), std::invalid_argument);
  EXPECT_NO_THROW(mesh_of({{0, 1, 0, 1}, {1, 2, 0, 1}, {0, 2, 1, 2}}, {trig(3)}));
}

TEST(TmeshMesh, DyadicHierarchicalMesh) {
  const TMesh m = mesh_of(dyadic(), {trig(3)}, pi / 8);
  EXPECT_EQ(m.admissibility_problem(), "");
  EXPECT_EQ(m.num_non_t_vertices(), 13);
  EXPECT_EQ(int(m.vertices().size()) - m.num_non_t_vertices(), 6);
  EXPECT_EQ(m.edges().size(), 22u);
  // Vertex lookup on the lattice: corners and T-junctions, nothing between them.
  for (int v = 0; v < static_cast<int>(m.vertices().size()); ++v) EXPECT_EQ(m.vertex_at(m.vertices()[v].x, m.vertices()[v].y), v);
  ASSERT_GE(m.vertex_at(2 * U, 3 * U), 0);
  EXPECT_TRUE(m.vertices()[m.vertex_at(2 * U, 3 * U)].t_junction);  // inside the right side of [0, 2] x [2, 4]
  EXPECT_EQ(m.vertex_at(U, U / 2), -1);
  EXPECT_EQ(m.dimension_formula(1, 1), 52);
  EXPECT_EQ(m.dimension_formula(0, 0), 97);
  EXPECT_EQ(mesh_of(dyadic(), {trig(2)}, pi / 8).dimension_formula(0, 0), 45);
  EXPECT_EQ(mesh_of(dyadic(), {trig(5)}, pi / 8).dimension_formula(1, 1), 180);
  EXPECT_EQ(brute_force_dimension(m, 1, 1), 52);
  EXPECT_EQ(brute_force_dimension(m, 0, 0), 97);
  // Uniform refinement keeps it admissible and self-similar; a local refinement too.
  const TMesh fine = m.refined_uniformly();
  EXPECT_EQ(fine.num_cells(), 40);
  EXPECT_EQ(fine.admissibility_problem(), "");
  EXPECT_EQ(fine.dimension_formula(1, 1), brute_force_dimension(fine, 1, 1));
  const TMesh local = m.refined({0, 6});
  // Splitting cells alone, twice, then one mesh: the mesh of two refinements.
  const TMesh twice = m.refined({0, 6}).refined({1, 7});
  const TMesh at_once(TMesh::split_cells(TMesh::split_cells(m.cells(), {0, 6}), {1, 7}), m.sections(), {0, 0}, m.unit());
  ASSERT_EQ(at_once.num_cells(), twice.num_cells());
  for (int c = 0; c < twice.num_cells(); ++c) {
    const TCell &a = at_once.cells()[c], &b = twice.cells()[c];
    EXPECT_TRUE(a.x0 == b.x0 && a.x1 == b.x1 && a.y0 == b.y0 && a.y1 == b.y1) << "cell " << c;
  }
  EXPECT_EQ(at_once.edges().size(), twice.edges().size());
  EXPECT_EQ(local.admissibility_problem(), "");
  EXPECT_EQ(local.dimension_formula(1, 1), brute_force_dimension(local, 1, 1));
  const TMesh local2 = mesh_of(dyadic(), {poly(2)}, pi / 8).refined({1, 4});
  EXPECT_EQ(local2.dimension_formula(0, 0), brute_force_dimension(local2, 0, 0));
}

TEST(TmeshMesh, InsertionSequenceOfTheNotes) {
  // Strips family, (5,5)/(1,1) trig w = 1 (notes §4.3): 84, 92, 100, 116, 140.
  auto dim = [](const std::vector<Box>& b) { return mesh_of(b, {trig(5)}, 0.5).dimension_formula(1, 1); };
  EXPECT_EQ(dim({{0, 2, 0, 6}, {2, 4, 0, 6}, {4, 6, 0, 6}}), 84);
  EXPECT_EQ(dim({{0, 2, 0, 6}, {2, 4, 0, 3}, {2, 4, 3, 6}, {4, 6, 0, 6}}), 92);
  EXPECT_EQ(dim({{0, 2, 0, 2}, {0, 2, 2, 6}, {2, 4, 0, 6}, {4, 6, 0, 6}}), 100);
  EXPECT_EQ(dim({{0, 2, 0, 3}, {0, 2, 3, 6}, {2, 4, 0, 3}, {2, 4, 3, 6}, {4, 6, 0, 6}}), 116);
  EXPECT_EQ(dim({{0, 2, 0, 3}, {0, 2, 3, 6}, {2, 4, 0, 3}, {2, 4, 3, 6}, {4, 6, 0, 3}, {4, 6, 3, 6}}), 140);
}
