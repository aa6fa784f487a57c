/// @file
/// The 4-split G1 space built on a rank's part without the whole mesh's local problems: the
/// skeleton numbers the functions from per-vertex and per-edge counts (G14LocalProblems::
/// count_functions) exactly as the whole basis numbers them, and refuses a degree below the
/// separability degree with the whole basis's error; a part solves the local problems of the
/// entities at its faces and has the whole space's active functions, extractions and values on them.

#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>
#include <string>
#include <tuple>

#include "tests/support/input_error.hpp"
#include "spaces/g1_4split/g14_local_problems.hpp"
#include "spaces/g1_4split/g1_4split_basis.hpp"
#include "spaces/g1_4split/g1_4split_meshes.hpp"
#include "spaces/g1_4split/g1_4split_space.hpp"
#include "tests/support/build_on_checks.hpp"

namespace iga {
namespace {

/// The extractions of `part` on `elements` are the whole space's, entry for entry.
void expect_same_extractions(const G14Space& part, const G14Space& whole, const std::vector<int>& elements) {
  for (int e : elements) {
    const Eigen::MatrixXd a(part.extraction(e)), b(whole.extraction(e));
    ASSERT_EQ(a.rows(), b.rows()) << e;
    ASSERT_EQ(a.cols(), b.cols()) << e;
    EXPECT_TRUE((a.array() == b.array()).all()) << e;
  }
}

TEST(G14Parts, TheCountsNumberTheFunctionsAsTheWholeBasisAndEveryFunctionOfAFaceLivesOnIt) {
  // fan3 / fan5: interior vertices of valence 3 / 5, boundary vertices with 1 and 2 faces, and on
  // level 1 valence-4 vertices with crossing edges (a = 0 inside the coarse faces).
  for (const char* name : {"fan3", "fan5", "halffan3"})
    for (Blending blending : {Blending::lines, Blending::q1}) {
      const QuadTopology coarse = quad_topology(g14_domain(name));
      const std::vector<SplitGluing> g0 = symmetric_gluing(coarse, blending);
      const QuadTopology fine = coarse.refined();
      const std::vector<SplitGluing> g1 = inherited_gluing(coarse, g0, fine);
      for (const auto& [t, g] : {std::pair(&coarse, &g0), std::pair(&fine, &g1)}) {
        const G14Basis whole = build_g14_basis(*t, *g, 5, 1);
        const SplitBSpline b(5, 1);
        const G14Numbering counted = G14LocalProblems(*t, *g, b).count_functions();
        EXPECT_EQ(counted.vertex_first, whole.numbering.vertex_first) << name;
        EXPECT_EQ(counted.edge_first, whole.numbering.edge_first) << name;
        EXPECT_EQ(counted.per_face, (2 * 5 - 1 - 3) * (2 * 5 - 1 - 3)) << name;  // (2k - r - 3)² (notes §7)
        EXPECT_EQ(counted.dimension(t->num_faces()), whole.dimension()) << name;
        EXPECT_EQ(whole.dimension(), g14_dimension_formula(*t, *g, 5, 1)) << name;
        // Numbered by entity, each face's functions are those non-zero on it: no zero column.
        for (int f = 0; f < t->num_faces(); ++f)
          for (int j = 0; j < whole.extraction[f].cols(); ++j)
            EXPECT_GT(whole.extraction[f].col(j).norm(), 0.0) << name << " face " << f << " function " << j;
      }
    }
}

/// The error build_g14_basis throws (NotSeparable), or "" when it builds.
template <class Build>
std::string refusal(const Build& build) {
  return test::message_of<NotSeparable>(build);
}

TEST(G14Parts, TheCountsRefuseADegreeBelowSeparabilityAsTheWholeBasis) {
  // Below the separability degree (g14_dimension_test): fan3 at k = 3 and fan5+ at k = 4 with the
  // paper's q0 gluing, and their refined meshes with the inherited gluing.
  int refused = 0;
  for (const auto& [name, k] : {std::pair("fan3", 3), std::pair("fan5+", 4)}) {
    const QuadTopology coarse = std::string(name) == "fan5+" ? fan_topology(5, true) : quad_topology(g14_domain(name));
    const std::vector<SplitGluing> g0 = symmetric_gluing(coarse, Blending::q0);
    const QuadTopology fine = coarse.refined();
    const std::vector<SplitGluing> g1 = inherited_gluing(coarse, g0, fine);
    const SplitBSpline b(k, 1);
    for (const auto& [t, g] : {std::pair(&coarse, &g0), std::pair(&fine, &g1)}) {
      const std::string whole = refusal([&] { build_g14_basis(*t, *g, k, 1); });
      const std::string counted = refusal([&] { G14LocalProblems(*t, *g, b).count_functions(); });
      EXPECT_EQ(counted, whole) << name << " " << t->num_faces() << " faces";  // the same vertex, edge and residual
      refused += whole.empty() ? 0 : 1;
    }
  }
  EXPECT_GE(refused, 2);
}

TEST(G14Parts, APartHasTheWholeSpacesFunctionsExtractionsAndValuesOnItsFaces) {
  // fan5 with q1 on level 2 (80 faces: gluing and geometry inherited twice), fan3 with the default
  // `lines` on level 1 (12 faces).
  for (const auto& [name, blending, level] : {std::tuple("fan5", Blending::q1, 2), std::tuple("fan3", Blending::lines, 1)}) {
    G14Options o;
    o.degree = 5;
    o.blending = blending;
    o.level = level;
    const auto whole = std::make_shared<const G14Space>(g14_domain(name), o);
    o.extent = SpaceExtent::skeleton;
    const auto skeleton = std::make_shared<const G14Space>(g14_domain(name), o);
    test::expect_skeleton_of(*skeleton, *whole);
    const int n = skeleton->num_elements();
    // The skeleton keeps the level-0 map; each face's, subdivided along its path, is the whole's.
    EXPECT_TRUE(skeleton->geometry().x.empty());
    for (int f = 0; f < n; ++f) {
      NestedGeometry::Path path;
      const Eigen::VectorXd *x, *y;
      skeleton->face_geometry(f, path, x, y);
      EXPECT_TRUE(*x == whole->geometry().x[f] && *y == whole->geometry().y[f]) << name << " face " << f;
    }
    // The first third (a rank's block of faces), every fifth face, the last face alone.
    std::vector<int> block, spread, last{n - 1};
    for (int e = 0; e < n / 3; ++e) block.push_back(e);
    for (int e = 2; e < n; e += 5) spread.push_back(e);
    for (const std::vector<int>* set : {&block, &spread, &last}) {
      const SpacePtr part = on_elements(skeleton, *set);
      test::expect_built_as_whole(*part, *whole, *set, 6);
      expect_same_extractions(dynamic_cast<const G14Space&>(*part), *whole, *set);
    }
    // A space built on some faces asked for others: built from the skeleton again.
    const SpacePtr again = on_elements(on_elements(skeleton, spread), block);
    test::expect_built_as_whole(*again, *whole, block, 6);
  }
}

}  // namespace
}  // namespace iga
