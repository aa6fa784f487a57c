// The structural check of .msh files (ASCII MSH 2.2 and 4.1) in our own code, before Gmsh reads
// them: each malformed variant of two valid files is refused naming the file and the line; the
// valid files pass and read to the same square. Also non-finite coordinates in OBJ and OFF files.

#include "mesh/msh_structure_check.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "config/errors.hpp"
#include "mesh/read_mesh_file.hpp"
#include "tests/support/scratch_files.hpp"

namespace iga {
namespace {

const std::string data_dir = std::string(IGA_SOURCE_DIR) + "/tests/support/data/";

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// `text` with the first `from` replaced by `to` (which must occur).
std::string mutate(const std::string& text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.substr(0, at) + to + text.substr(at + from.size());
}

/// The 1-based line on which `snippet` first occurs in `text`.
int line_of(const std::string& text, const std::string& snippet) {
  const auto at = text.find(snippet);
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
}

std::string refusal(const std::string& name, const std::string& text, const MeshLimits& limits = {}) {
  const std::string path = test::scratch_file(name, text);
  try {
    check_msh_structure(path, limits);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << name << ": not refused";
  return "";
}

double total_area(const PlanarMesh& m) {
  double a = 0.0;
  for (int c = 0; c < static_cast<int>(m.cells.size()); ++c) a += 0.5 * twice_signed_area(m, c);
  return a;
}

TEST(MshStructureCheck, ValidFilesPassAndRead) {
  for (const char* name : {"square_groups.msh", "square_groups_v22.msh"}) {
    EXPECT_NO_THROW(check_msh_structure(data_dir + name)) << name;
    const PlanarMesh m = read_mesh_file(data_dir + name);
    EXPECT_NEAR(total_area(m), 1.0, 1e-14) << name;
    ASSERT_EQ(m.boundary_groups.size(), 3u) << name;
    for (const char* group : {"bottom", "sides", "7"}) EXPECT_EQ(m.boundary_groups.count(group), 1u) << group;
  }
  // MSH 2.2, 4 triangles around the centre: every node is used.
  EXPECT_EQ(read_mesh_file(data_dir + "square_groups_v22.msh").cells.size(), 4u);
}

struct Case {
  std::string from, to;  ///< the mutation
  std::string at;        ///< a snippet on the line the message names ("" for no line)
  std::string expected;  ///< part of the message
};

void expect_refusals(const std::string& base, const std::string& prefix, const std::vector<Case>& cases) {
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const std::string text = mutate(base, cases[k].from, cases[k].to);
    const std::string name = prefix + std::to_string(k) + ".msh";
    const std::string path = (test::scratch_folder() / name).string();
    const std::string message = refusal(name, text);
    const std::string where =
        cases[k].at.empty() ? path + ": " : path + ":" + std::to_string(line_of(text, cases[k].at)) + ": ";
    EXPECT_EQ(message.rfind(where, 0), 0u) << cases[k].to << " -> " << message;
    EXPECT_NE(message.find(cases[k].expected), std::string::npos) << cases[k].to << " -> " << message;
    // read_mesh_file refuses the same way, before Gmsh reads anything.
    try {
      read_mesh_file(path);
      ADD_FAILURE() << name << " read";
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()), message);
    }
  }
}

TEST(MshStructureCheck, MalformedVersion2FilesAreRefusedNamingTheLine) {
  const std::string base = read_text(data_dir + "square_groups_v22.msh");
  expect_refusals(
      base, "v2_",
      {
          {"$MeshFormat\n", "$Mesh\n", "$Mesh", "expected '$MeshFormat' as the first line"},
          {"2.2 0 8", "2.2 1 8", "2.2 1 8", "binary .msh files are not supported"},
          {"2.2 0 8", "3.0 0 8", "3.0 0 8", "MSH version 3.0 is not supported"},
          {"2.2 0 8", "4.0 0 8", "4.0 0 8", "MSH version 4.0 is not supported"},
          {"$Nodes\n5\n", "$Nodes\n4\n", "5 0.5 0.5 0",
           "expected '$EndNodes' (the counts above do not match the data)"},
          {"$Nodes\n5\n", "$Nodes\n6\n", "$EndNodes", "expected node 6 of 6, got '$EndNodes'"},
          {"$Elements\n8\n", "$Elements\n9\n", "$EndElements", "expected element 9 of 9"},
          {"5 2 2 8 1 1 2 5", "5 2 2 8 1 1 2 9", "5 2 2 8 1 1 2 9",
           "the element uses node 9, which the $Nodes section does not define"},
          {"5 2 2 8 1 1 2 5", "5 2 2 8 1 1 2 0", "5 2 2 8 1 1 2 0", "node tag 0 is not in [1, 2147483647]"},
          {"5 2 2 8 1 1 2 5", "5 2 2 8 1 1 2 -5", "5 2 2 8 1 1 2 -5", "node tag -5 is not in"},
          {"5 2 2 8 1 1 2 5", "5 2 2 8 1 1 2 99999999999", "99999999999", "node tag 99999999999 is not in"},
          {"5 2 2 8 1 1 2 5", "5 2 2 8 1 1 2 5.5", "5.5", "expected node tag (an integer), got '5.5'"},
          {"5 2 2 8 1 1 2 5", "5 2 2 8 1 1 2", "5 2 2 8 1 1 2\n", "element type 2 needs 3 node tags, the line has 2"},
          {"5 2 2 8 1 1 2 5", "5 77 2 8 1 1 2 5", "5 77", "element type 77 is not a Gmsh element type"},
          {"6 2 2 8 1 2 3 5", "5 2 2 8 1 2 3 5", "5 2 2 8 1 2 3 5", "element 5 is defined twice"},
          {"2 1 0 0", "1 1 0 0", "1 1 0 0", "node 1 is defined twice"},
          {"5 0.5 0.5 0", "5 nan 0.5 0", "5 nan", "coordinate 'nan' is not finite"},
          {"5 0.5 0.5 0", "5 0.5 inf 0", "5 0.5 inf", "coordinate 'inf' is not finite"},
          {"5 0.5 0.5 0", "5 0.5 0.5 1e999", "1e999", "expected a coordinate, got '1e999'"},
          {"1 1 \"bottom\"", "1 1 bottom", "1 1 bottom", "the physical name must be in double quotes"},
          {"$EndElements\n", "", "", "$Elements is not closed by $EndElements"},
          {"$EndNodes\n", "$EndNode\n", "$EndNode", "expected '$EndNodes'"},
          {"$Nodes\n", "$Knots\n", "", "$Knots is not closed by $EndKnots"},
          {"$EndMeshFormat\n", "$EndMeshFormat\n$Comments\nanything\n", "", "$Comments is not closed by $EndComments"},
          {"$PhysicalNames\n", "$EndPhysicalNames\n$PhysicalNames\n", "$EndPhysicalNames\n$PhysicalNames",
           "'$EndPhysicalNames' closes no open section"},
          {"$Elements\n8\n", "$Elements\n-1\n", "-1", "element count is negative"},
      });
}

TEST(MshStructureCheck, MalformedVersion4FilesAreRefusedNamingTheLine) {
  const std::string base = read_text(data_dir + "square_groups.msh");
  expect_refusals(
      base, "v4_",
      {
          {"9 12 1 12", "9 13 1 12", "9 13 1 12", "the blocks have 12 nodes, the header says 13"},
          {"9 12 1 12", "9 11 1 12", "2 1 0 4", "the blocks have more nodes than the header's 11"},
          {"9 12 1 12", "9 12 1 40", "9 12 1 40", "node tags run from 1 to 12, the header says 1 to 40"},
          {"5 22 1 22", "5 23 1 22", "5 23 1 22", "the blocks have 22 elements, the header says 23"},
          {"2 1 2 14", "2 5 2 14", "2 5 2 14", "the block refers to entity (dim 2, tag 5)"},
          {"2 1 2 14", "1 1 2 14", "9 6 3 11", "element type 2 has dimension 2, the block's entity 1"},
          {"9 6 3 11", "9 6 3 13", "9 6 3 13", "the element uses node 13, which the $Nodes section does not define"},
          {"0.2937500000004586 0.7062500000004164 0", "0.2937500000004586 nan 0", "0.2937500000004586 nan",
           "coordinate 'nan' is not finite"},
          {"0.2937500000004586 0.7062500000004164 0", "0.29 0.70", "0.29 0.70", "expected 3 coordinates"},
          {"4.1 0 8", "4.1 1 8", "4.1 1 8", "binary .msh files are not supported"},
          {"$Entities\n", "$PartitionedEntities\n", "$PartitionedEntities", "partitioned meshes are not supported"},
      });
}

TEST(MshStructureCheck, MissingSectionsAreNamed) {
  const std::string base = read_text(data_dir + "square_groups_v22.msh");
  const std::string no_nodes = mutate(mutate(base, "$Nodes\n", "$Knots\n"), "$EndNodes\n", "$EndKnots\n");
  const std::string path = (test::scratch_folder() / "no_nodes.msh").string();
  EXPECT_EQ(refusal("no_nodes.msh", no_nodes), path + ": the file has no $Nodes section");
  const std::string no_elements = base.substr(0, base.find("$Elements"));
  EXPECT_EQ(refusal("no_elements.msh", no_elements),
            (test::scratch_folder() / "no_elements.msh").string() + ": the file has no $Elements section");
  EXPECT_NE(refusal("empty.msh", "").find("empty.msh:0: expected '$MeshFormat' as the first line"), std::string::npos);
}

TEST(MshStructureCheck, SizesAreLimitedBeforeReading) {
  const std::string base = read_text(data_dir + "square_groups_v22.msh");
  MeshLimits limits;
  limits.max_elements = 3;
  // 4 triangles against a limit of 3 (the 8 elements in all are within 4 x 3).
  const std::string path = (test::scratch_folder() / "limit_2d.msh").string();
  EXPECT_EQ(refusal("limit_2d.msh", base, limits), path + ": the mesh has 4 2D elements, more than the limit of 3 (limits.max_elements in the config)");
  // A header count beyond 2 x the limit is refused at its line, before anything is read.
  const std::string huge = mutate(base, "$Nodes\n5\n", "$Nodes\n1000000000000\n");
  EXPECT_NE(refusal("limit_header.msh", huge).find(":11: node count 1000000000000 is more than the limit of 8e+06"),
            std::string::npos);
}

TEST(NonFiniteCoordinates, ObjAndOffNameTheLine) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n"},
      {"inf.obj", "v 0 0 0\nv 1 -inf 0\nv 0 1 0\nf 1 2 3\n"},
      {"nan.off", "OFF\n3 1 0\n0 0 0\n1 0 nan\n0 1 0\n3 0 1 2\n"},
  };
  const std::vector<std::string> expected = {":2: the coordinate 'nan' is not finite",
                                             ":2: the coordinate '-inf' is not finite",
                                             ":4: the coordinate 'nan' is not finite"};
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const std::string path = test::scratch_file(cases[k].first, cases[k].second);
    try {
      read_mesh_file(path);
      ADD_FAILURE() << path << " read";
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()).rfind(path + expected[k], 0), 0u) << e.what();
    }
  }
}

}  // namespace
}  // namespace iga
