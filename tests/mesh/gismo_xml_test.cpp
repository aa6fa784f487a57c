// G+Smo XML geometry files: the shipped 3p_square read as patches and as a mesh of quadrilaterals,
// and every refusal (malformed or hostile XML, what a bilinear multipatch cannot be) with the file,
// element and line named.
#include "mesh/gismo_xml.hpp"

#include <gtest/gtest.h>

#include <set>

#include "tests/support/input_error.hpp"
#include "tests/support/scratch_files.hpp"

namespace iga {
namespace {

using test::input_error;
using test::scratch_file;

const std::string shipped = std::string(IGA_SOURCE_DIR) + "/configs/domains/3p_square.xml";

/// One bilinear TensorBSpline2 with the given corners p00 p10 p01 p11 (and an id).
std::string bilinear(int id, const std::string& coefs, int degree = 1, const std::string& knots = "0 0 1 1") {
  return " <Geometry type=\"TensorBSpline2\" id=\"" + std::to_string(id) +
         "\">\n  <Basis type=\"TensorBSplineBasis2\">\n"
         "   <Basis type=\"BSplineBasis\" index=\"0\"><KnotVector degree=\"" + std::to_string(degree) + "\">" + knots +
         "</KnotVector></Basis>\n"
         "   <Basis type=\"BSplineBasis\" index=\"1\"><KnotVector degree=\"1\">0 0 1 1</KnotVector></Basis>\n"
         "  </Basis>\n  <coefs geoDim=\"2\">" + coefs + "</coefs>\n </Geometry>\n";
}

/// Two unit squares side by side, [0,1]x[0,1] and [1,2]x[0,1], with `topology` inside <MultiPatch>.
std::string two_squares(const std::string& topology) {
  return "<xml>\n" + bilinear(0, "0 0 1 0 0 1 1 1") + bilinear(1, "1 0 2 0 1 1 2 1") +
         " <MultiPatch parDim=\"2\" id=\"2\">\n  <patches type=\"id_range\">0 1</patches>\n" + topology +
         " </MultiPatch>\n</xml>\n";
}

TEST(GismoXml, ShippedThreePatchSquare) {
  const GismoMultiPatch mp = read_gismo_xml(shipped);
  ASSERT_EQ(mp.patches.size(), 3u);
  EXPECT_EQ(mp.interfaces.size(), 3u);
  ASSERT_EQ(mp.boundary.size(), 1u);
  EXPECT_EQ(mp.boundary[0].second.size(), 6u);
  EXPECT_EQ(mp.patches[1].control_points[1], Eigen::Vector2d(1, 0.7));
  const PlanarMesh mesh = bilinear_patch_mesh(mp);
  EXPECT_EQ(mesh.vertices.size(), 7u);  // corners of the square, (0.4, 0), (1, 0.7), (0, 1) and (0.6, 0.6)
  EXPECT_EQ(mesh.cells.size(), 3u);
  double area = 0.0;
  for (int c = 0; c < 3; ++c) {
    EXPECT_GT(twice_signed_area(mesh, c), 0.0);
    area += 0.5 * twice_signed_area(mesh, c);
  }
  EXPECT_NEAR(area, 1.0, 1e-15);
  EXPECT_EQ(boundary_edges(mesh).size(), 6u);  // V - E + F = 7 - 9 + 3 = 1
}

TEST(GismoXml, SinglePatchWithoutMultiPatch) {
  const std::string f = scratch_file("single.xml", "<?xml version=\"1.0\"?>\n<xml>\n" +
                                                       bilinear(5, "0 0 2 0 0 1 2 1", 2, "0 0 0 0.5 1 1 1") + "</xml>\n");
  // Degree 2 with 7 knots: 4 x 2 control points needed, 4 given.
  EXPECT_NE(input_error([&] { read_gismo_xml(f); }).find("single.xml:8: <coefs>: the knot vectors need 4 x 2"),
            std::string::npos);
  const std::string g = scratch_file("single_ok.xml", "<xml>\n" +
                                                          bilinear(5, "0 0 1 0 2 0 3 0 0 1 1 1 2 1 3 1", 2, "0 0 0 0.5 1 1 1") +
                                                          "</xml>\n");
  const GismoMultiPatch mp = read_gismo_xml(g);
  const GismoPatch& p = single_gismo_patch(mp, "bspline");
  EXPECT_EQ(p.id, 5);
  EXPECT_EQ(p.degree[0], 2);
  EXPECT_EQ(p.control_points.size(), 8u);
  // A patch of degree 2 is not a corner of a quadrilateral mesh.
  const std::string msg = input_error([&] { bilinear_patch_mesh(mp); });
  EXPECT_NE(msg.find("patch 0, Geometry id 5 (line 2): degree (2, 1)"), std::string::npos) << msg;
  EXPECT_NE(msg.find("not bilinear"), std::string::npos) << msg;
}

TEST(GismoXml, SinglePatchSpaceRefusesMultipatch) {
  const std::string msg = input_error([&] { single_gismo_patch(read_gismo_xml(shipped), "bspline"); });
  EXPECT_NE(msg.find("3 patches: the bspline space takes a single patch"), std::string::npos) << msg;
}

TEST(GismoXml, TopologyIsCheckedAgainstTheGeometry) {
  // Listed correctly: east of patch 0 is west of patch 1.
  const PlanarMesh ok = bilinear_patch_mesh(read_gismo_xml(scratch_file(
      "ok.xml", two_squares("  <interfaces>0 2 1 1 0 1 1 1</interfaces>\n  <boundary name=\"left\">0 1</boundary>\n"))));
  EXPECT_EQ(ok.vertices.size(), 6u);
  ASSERT_EQ(ok.boundary_groups.count("left"), 1u);
  EXPECT_EQ(ok.boundary_groups.at("left").size(), 1u);

  const std::string unlisted = input_error([&] {
    bilinear_patch_mesh(read_gismo_xml(scratch_file("unlisted.xml", two_squares("  <interfaces></interfaces>\n"))));
  });
  EXPECT_NE(unlisted.find("patch 0 side 2 (east) and patch 1 side 1 (west) have the same corners but <interfaces> does not list them"),
            std::string::npos)
      << unlisted;
  const std::string wrong = input_error([&] {
    bilinear_patch_mesh(read_gismo_xml(scratch_file("wrong.xml", two_squares("  <interfaces>0 3 1 1 0 1 1 1</interfaces>\n"))));
  });
  EXPECT_NE(wrong.find("wrong.xml:18: <interfaces>: patch 0 side 3 (south) and patch 1 side 1 (west) do not have the same corners"),
            std::string::npos)
      << wrong;
  const std::string interior = input_error([&] {
    bilinear_patch_mesh(read_gismo_xml(scratch_file("interior.xml", two_squares("  <boundary>0 2</boundary>\n"))));
  });
  EXPECT_NE(interior.find("<boundary>: patch 0 side 2 (east) is shared with another patch"), std::string::npos) << interior;
  EXPECT_NE(input_error([&] { read_gismo_xml(scratch_file("side.xml", two_squares("  <boundary>0 5</boundary>\n"))); })
                .find("side.xml:18: <boundary>: side 5"),
            std::string::npos);
  EXPECT_NE(input_error([&] { read_gismo_xml(scratch_file("patch.xml", two_squares("  <boundary>2 1</boundary>\n"))); })
                .find("patch index 2 (the multipatch has patches 0..1)"),
            std::string::npos);
  EXPECT_NE(input_error([&] { read_gismo_xml(scratch_file("eight.xml", two_squares("  <interfaces>0 2 1 1</interfaces>\n"))); })
                .find("4 numbers; each interface is 8"),
            std::string::npos);
}

TEST(GismoXml, RationalPatchesWithUnequalWeightsAreNotBilinear) {
  const std::string nurbs =
      "<xml>\n <Geometry type=\"TensorNurbs2\" id=\"0\">\n  <Basis type=\"TensorNurbsBasis2\">\n"
      "   <Basis type=\"TensorBSplineBasis2\">\n"
      "    <Basis type=\"BSplineBasis\" index=\"0\"><KnotVector degree=\"1\">0 0 1 1</KnotVector></Basis>\n"
      "    <Basis type=\"BSplineBasis\" index=\"1\"><KnotVector degree=\"1\">0 0 1 1</KnotVector></Basis>\n"
      "   </Basis>\n   <weights>1 1 1 WEIGHT</weights>\n  </Basis>\n"
      "  <coefs geoDim=\"3\">0 0 0 1 0 0 0 1 0 1 1 0</coefs>\n </Geometry>\n</xml>\n";
  const auto with = [&](const std::string& w) {
    std::string t = nurbs;
    t.replace(t.find("WEIGHT"), 6, w);
    return t;
  };
  EXPECT_EQ(bilinear_patch_mesh(read_gismo_xml(scratch_file("equal.xml", with("1")))).cells.size(), 1u);
  EXPECT_NE(input_error([&] { bilinear_patch_mesh(read_gismo_xml(scratch_file("unequal.xml", with("2")))); })
                .find("a rational patch with unequal weights is not bilinear"),
            std::string::npos);
  EXPECT_NE(input_error([&] { read_gismo_xml(scratch_file("negative.xml", with("-1"))); })
                .find("negative.xml:8: <weights>: weights must be positive (weight 3 is -1)"),
            std::string::npos);
  EXPECT_NE(input_error([&] { read_gismo_xml(scratch_file("nan.xml", with("nan"))); }).find("'nan' is not finite"),
            std::string::npos);
  EXPECT_NE(input_error([&] { read_gismo_xml(scratch_file("word.xml", with("1e"))); }).find("'1e' is not a number"),
            std::string::npos);
}

TEST(GismoXml, MalformedAndHostileFilesAreRefused) {
  struct Case {
    const char* name;
    std::string text;
    const char* message;
  };
  std::string deep;  // nesting beyond tinyxml2's depth limit
  for (int i = 0; i < 1000; ++i) deep += "<xml>";
  const std::vector<Case> cases = {
      {"unclosed.xml", "<xml>\n <Geometry type=\"TensorBSpline2\">\n</xml>\n", "unclosed.xml:2: not well-formed XML"},
      {"empty.xml", "", "not well-formed XML"},
      {"root.xml", "<gismo></gismo>", "root.xml:1: <gismo>: a G+Smo file has the root element <xml>"},
      {"nothing.xml", "<xml/>", "no <Geometry> and no <MultiPatch>"},
      // Entity expansion (a "billion laughs") and external entities are declared in a DTD: refused.
      {"laughs.xml",
       "<?xml version=\"1.0\"?>\n<!DOCTYPE xml [\n <!ENTITY a \"aaaaaaaaaa\">\n <!ENTITY b \"&a;&a;&a;&a;&a;&a;&a;&a;\">\n]>\n"
       "<xml>&b;</xml>\n",
       "laughs.xml:2: DTDs and other <!...> declarations are not accepted"},
      {"external.xml",
       "<?xml version=\"1.0\"?>\n<!DOCTYPE xml [<!ENTITY secret SYSTEM \"file:///etc/passwd\">]>\n<xml>&secret;</xml>\n",
       "external.xml:2: DTDs and other <!...> declarations are not accepted"},
      {"deep.xml", deep, "not well-formed XML"},
      {"type.xml", "<xml>\n<Geometry type=\"TensorBSpline3\" id=\"0\"/>\n</xml>",
       "type.xml:2: <Geometry>: type 'TensorBSpline3' is not supported (supported: TensorBSpline2, TensorNurbs2)"},
      {"twice.xml", "<xml>\n" + bilinear(0, "0 0 1 0 0 1 1 1") + bilinear(0, "0 0 1 0 0 1 1 1") + "</xml>",
       "twice.xml:9: <Geometry>: a second Geometry with id 0"},
      {"missing.xml",
       "<xml>\n" + bilinear(0, "0 0 1 0 0 1 1 1") + "<MultiPatch><patches type=\"id_range\">0 1</patches></MultiPatch></xml>",
       "missing.xml:9: <patches>: no Geometry with id 1"},
      {"degree.xml", "<xml>\n" + bilinear(0, "0 0 1 0 0 1 1 1", 99, "0 1") + "</xml>", "degree.xml:4: <KnotVector>: degree 99"},
      {"knots.xml", "<xml>\n" + bilinear(0, "0 0 1 0 0 1 1 1", 1, "0 1 0.5 1") + "</xml>",
       "knots.xml:4: <KnotVector>: the knots decrease at position 2"},
      {"z.xml",
       "<xml>\n" + std::string(bilinear(0, "0 0 1 0 0 1 1 1")).replace(bilinear(0, "").find("geoDim=\"2\""), 10, "geoDim=\"3\"") +
           "</xml>",
       "the knot vectors need 2 x 2 control points of 3 coordinates"},
  };
  for (const Case& c : cases) {
    const std::string msg = input_error([&] { read_gismo_xml(scratch_file(c.name, c.text)); });
    EXPECT_NE(msg.find(c.message), std::string::npos) << c.name << ": " << msg;
  }
}

TEST(GismoXml, SizeLimit) {
  GismoXmlLimits limits;
  limits.max_bytes = 100;
  const std::string msg = input_error([&] { read_gismo_xml(shipped, limits); });
  EXPECT_NE(msg.find("more than the limit of 100 for a geometry file"), std::string::npos) << msg;
  EXPECT_NE(input_error([&] { read_gismo_xml("/nonexistent/domain.xml"); }).find("cannot read the geometry file"),
            std::string::npos);
}

}  // namespace
}  // namespace iga
