/// @file
/// A G1 space built on some of its elements (BuildsOnElements, what one rank of a distributed
/// solve keeps): the skeleton has the whole numbering and geometry and no extraction (it numbers
/// the functions from per-entity counts, g1_numbering.hpp), the space built on a set of elements
/// evaluates them bit for bit as the whole space does, and asking it for another element is a
/// programming error.

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <memory>
#include <string>

#include "config/errors.hpp"
#include "spaces/g1/g1_numbering.hpp"
#include "spaces/g1/g1_space.hpp"
#include "spaces/g1/multipatch_domains.hpp"
#include "tests/support/build_on_checks.hpp"

namespace iga {
namespace {

using P = Point2;

/// `built` (on `elements`) has exactly the whole space's active functions and extraction matrices
/// on those elements, entry for entry, and keeps nothing of the other elements.
void expect_same_extraction(const G1Space& built, const G1Space& whole, const std::vector<int>& elements) {
  ASSERT_EQ(built.basis().extraction.size(), elements.size());
  ASSERT_EQ(built.basis().face_dofs.size(), elements.size());
  EXPECT_TRUE(built.basis().info.empty());
  for (size_t s = 0; s < elements.size(); ++s) {
    const int e = elements[s];
    EXPECT_EQ(built.basis().face_dofs[s], whole.basis().face_dofs[e]) << e;
    const Eigen::MatrixXd a = built.basis().extraction[s], b = whole.basis().extraction[e];
    ASSERT_EQ(a.rows(), b.rows()) << e;
    ASSERT_EQ(a.cols(), b.cols()) << e;
    EXPECT_EQ((a - b).cwiseAbs().maxCoeff(), 0.0) << e;
    EXPECT_EQ(built.basis().extraction[s].nonZeros(), whole.basis().extraction[e].nonZeros()) << e;
  }
}

/// Skeleton against whole on `mesh` at degree k, then parts on several element sets: every third,
/// the first quarter (a block with an inner boundary), one element, the elements on the boundary.
void expect_parts_as_whole(const PatchMesh& m, int k) {
  SCOPED_TRACE(m.name() + " k=" + std::to_string(k));
  const auto mesh = std::make_shared<const PatchMesh>(m);
  const auto whole = std::make_shared<const G1Space>(mesh, k);
  const auto skeleton = std::make_shared<const G1Space>(mesh, k, SpaceExtent::skeleton);
  // The counts are Theorem 6.3's (notes Prop. 5.1 per vertex, d_τ(k) per edge).
  EXPECT_EQ(skeleton->dimension(), theorem_dimension(*mesh, whole->gluing(), k));
  test::expect_skeleton_of(*skeleton, *whole);
  const int n = skeleton->num_elements();
  std::vector<std::vector<int>> sets(4);
  for (int e = 0; e < n; e += 3) sets[0].push_back(e);
  for (int e = 0; e < n / 4; ++e) sets[1].push_back(e);
  sets[2] = {n / 2};
  for (const BoundaryEdge& b : skeleton->boundary_edges("all")) sets[3].push_back(b.element);
  std::sort(sets[3].begin(), sets[3].end());
  sets[3].erase(std::unique(sets[3].begin(), sets[3].end()), sets[3].end());
  for (const std::vector<int>& some : sets) {
    const SpacePtr built = on_elements(skeleton, some);
    test::expect_built_as_whole(*built, *whole, some, 2 * k);
    expect_same_extraction(dynamic_cast<const G1Space&>(*built), *whole, some);
  }
}

TEST(G1BuildOn, APartOfTheSkeletonEvaluatesItsElementsAsTheWholeSpaceAndRefusesTheOthers) {
  // The three-patch square refined twice: 48 quads with an extraordinary vertex of valence 3.
  const auto mesh = std::make_shared<const PatchMesh>(multipatch_domain("3p_square").refined().refined());
  const auto whole = std::make_shared<const G1Space>(mesh, 5);
  const auto skeleton = std::make_shared<const G1Space>(mesh, 5, SpaceExtent::skeleton);
  ASSERT_EQ(skeleton->num_elements(), 48);
  test::expect_skeleton_of(*skeleton, *whole);
  // Every third face; then the same again, which solves the local problems a second time.
  std::vector<int> some;
  for (int e = 0; e < skeleton->num_elements(); e += 3) some.push_back(e);
  for (int round = 0; round < 2; ++round) test::expect_built_as_whole(*on_elements(skeleton, some), *whole, some, 6);
}

TEST(G1BuildOn, TheSkeletonsNumberingIsTheWholeOnesWhereCountsVaryByVertex) {
  // Valence 3 (3p_square), 5 (5p_pentagon: an interior vertex of valence 5), triangles with
  // quads (2q2t_square) and triangles only around a non-crossing vertex (4t_star), once refined:
  // interior vertices of valence 3 to 6 and boundary vertices with one to three faces.
  expect_parts_as_whole(multipatch_domain("3p_square").refined(), 5);
  expect_parts_as_whole(multipatch_domain("5p_pentagon").refined(), 5);
  expect_parts_as_whole(multipatch_domain("2q2t_square").refined(), 5);
  expect_parts_as_whole(multipatch_domain("4t_star").refined(), 6);
}

TEST(G1BuildOn, TheSkeletonPerEntityCountsAreProposition51AndTheorem63) {
  const PatchMesh mesh = multipatch_domain("5p_pentagon").refined();
  const std::vector<EdgeGluing> gluing = gluing_from_geometry(mesh);
  const int k = 5;
  const G1Numbering n = number_g1_basis(mesh, gluing, k);
  for (int v = 0; v < mesh.num_vertices(); ++v)
    EXPECT_EQ(n.vertex_first[v + 1] - n.vertex_first[v], vertex_function_count(mesh, gluing, v)) << v;
  for (int e = 0; e < mesh.num_edges(); ++e) {
    const EdgeGluing& g = gluing[e];
    // Boundary edges: rows 0–1 minus the corner sets, 2(k − 3); interior: d_τ(k) − 9 + crossings.
    const int expected = mesh.edge(e).boundary() ? 2 * (k - 3)
                                                 : syzygy_dimension(g, k) - 9 + (g.crossing_x ? 1 : 0) + (g.crossing_y ? 1 : 0);
    EXPECT_EQ(n.edge_first[e + 1] - n.edge_first[e], expected) << e;
  }
  for (int f = 0; f < mesh.num_faces(); ++f) EXPECT_EQ(n.face_first[f + 1] - n.face_first[f], (k - 3) * (k - 3)) << f;
  EXPECT_EQ(n.dimension(), theorem_dimension(mesh, gluing, k));
}

std::string error_of(const std::shared_ptr<const PatchMesh>& mesh, int k, SpaceExtent extent) {
  try {
    G1Space(mesh, k, extent);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(G1BuildOn, TheSkeletonRefusesADegreeBelowSeparabilityWithTheWholeConstructionsMessage) {
  // T5 (three quads around a valence-3 vertex, notes §9.2: 45 of 48 functions at k = 4) and four
  // triangles around an off-centre vertex (notes §9.3: separable from k = 5) at k = 4; k = 3 on quads.
  const auto t5 = std::make_shared<const PatchMesh>(mesh_from_patches(
      {{P(0, 0), P(1, 0), P(0, 1), P(-1, 1)}, {P(0, 0), P(-1, 1), P(-1, 0), P(0, -1)}, {P(0, 0), P(0, -1), P(1, -1), P(1, 0)}},
      "T5"));
  const auto t9 = std::make_shared<const PatchMesh>(mesh_from_patches(
      {{P(0, 0), P(2, 0), P(0.9, 1.2)}, {P(2, 0), P(2, 2), P(0.9, 1.2)}, {P(2, 2), P(0, 2), P(0.9, 1.2)},
       {P(0, 2), P(0, 0), P(0.9, 1.2)}},
      "T9"));
  for (const auto& [mesh, k] : {std::pair{t5, 4}, std::pair{t9, 4}, std::pair{t5, 3}}) {
    const std::string whole = error_of(mesh, k, SpaceExtent::whole);
    EXPECT_NE(whole.find("use degree >= 5"), std::string::npos) << whole;
    EXPECT_EQ(error_of(mesh, k, SpaceExtent::skeleton), whole);
  }
}

}  // namespace
}  // namespace iga
