// The static check of .geo scripts: every statement that acts outside the geometry is refused
// with the file, the line and the statement named, before Gmsh runs; geometry scripts pass.

#include "mesh/geo_script_check.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>

#include "config/errors.hpp"
#include "mesh/read_mesh_file.hpp"
#include "tests/support/scratch_files.hpp"

namespace iga {
namespace {

namespace fs = std::filesystem;

const std::string source_dir = IGA_SOURCE_DIR;

std::string refusal(const std::string& name, const std::string& text) {
  const std::string path = test::scratch_file(name, text);
  try {
    check_geo_script(path, {test::scratch_folder()});
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << name << ": not refused";
  return "";
}

struct Refused {
  std::string text;      ///< the script (the offending statement on line 2)
  std::string expected;  ///< what the message says after "<file>:2: "
};

TEST(GeoScriptCheck, RefusedStatementsAreNamedWithFileAndLine) {
  const std::string marker = (test::scratch_folder() / "marker").string();
  const std::vector<Refused> cases = {
      {"SystemCall \"touch " + marker + "\";",
       "'SystemCall' is not allowed in a mesh script (it runs a shell command)"},
      {"System \"touch " + marker + "\";", "'System' is not allowed in a mesh script (it runs a shell command)"},
      {"NonBlockingSystemCall \"ls\";", "'NonBlockingSystemCall' is not allowed"},
      {"Save \"/tmp/anything.msh\";", "'Save' is not allowed in a mesh script (it writes a file)"},
      {"Print \"/tmp/picture.png\";", "'Print' is not allowed in a mesh script (it writes a file)"},
      {"Merge \"other.msh\";", "'Merge' is not allowed in a mesh script (it reads another file)"},
      {"ShapeFromFile(\"part.step\");", "'ShapeFromFile' is not allowed"},
      {"Exit;", "'Exit' is not allowed in a mesh script (it ends the process)"},
      {"Abort;", "'Abort' is not allowed"},
      {"Sleep 1e9;", "'Sleep' is not allowed in a mesh script (it waits)"},
      {"OnelabRun(\"solver\", \"cmd\");", "'OnelabRun' is not allowed in a mesh script (it runs a program)"},
      {"Plugin(Integrate).Run;", "'Plugin' is not allowed"},
      {"CreateDir \"/tmp/new\";", "'CreateDir' is not allowed in a mesh script (it creates a folder)"},
      {"home = GetEnv(\"HOME\");", "'GetEnv' is not allowed in a mesh script (it reads the environment)"},
      {"n = GetValue(\"how many?\", 3);", "'GetValue' is not allowed in a mesh script (it asks for input)"},
      {"Delete Physicals;", "'Physicals' is not allowed"},
      {"Delete Model;", "'Model' is not allowed"},
      {"Field[1] = ExternalProcess;", "'ExternalProcess' is not allowed in a mesh script (it runs a program)"},
      {"Field[1] = Structured;", "'Structured' is not allowed in a mesh script (it reads another file)"},
      {"Field[1] = PostView;", "the statement 'Field ...' is not allowed in a mesh script: the Field type 'PostView'"},
      {"Printf(\"x = %g\", 1) > \"/tmp/out.txt\";",
       "the statement 'Printf ...' is not allowed in a mesh script: Printf "
       "may not write to a file"},
      {"Printf(\"x\") >> \"log.txt\";", "Printf may not write to a file"},
      {"General.NumThreads = 64;",
       "the statement 'General ...' is not allowed in a mesh script: only Mesh.* and "
       "Geometry.* options may be set"},
      {"Solver.Executable0 = \"/bin/sh\";", "only Mesh.* and Geometry.* options may be set"},
      {"PostProcessing.Format = 1;", "only Mesh.* and Geometry.* options may be set"},
      {"Mesh.Format = \"msh\";", "options may only be set to numbers"},
      {"Mesh 2;", "the statement 'Mesh ...' is not allowed in a mesh script: meshing inside the script"},
      {"RefineMesh;",
       "the statement 'RefineMesh ...' is not allowed in a mesh script: it is neither an assignment nor "
       "a geometry or mesh statement"},
      {"OptimizeMesh \"Netgen\";", "the statement 'OptimizeMesh ...' is not allowed"},
      {"Include \"/etc/passwd\";",
       "the statement 'Include ...' is not allowed in a mesh script: '/etc/passwd' is "
       "outside the folder of the config and the mesh file"},
      {"Include \"../../etc/hostname\";", "is outside the folder"},
      {"Include StrCat(\"a\", \".geo\");", "Include needs a literal \"path\""},
      {"For i In {1:1e12}\nEndFor", "the range 1:1e+12 has 1e+12 values, more than the limit of 1e+06"},
      {"n = 1e7; For (1:2*n) EndFor", "the range 1:2e+07 has 2e+07 values"},
      {"For i In {0:10:0}\nEndFor", "a range with step 0 never ends"},
      {"x[] = {1:1e10};", "the range 1:1e+10 has 1e+10 values"},
      {"\"x\";", "a statement cannot start with 'x'"},
      {"x = 1", "the statement 'x ...' does not end with ';'"},
      {"s = \"open", "unterminated string"},
      {"/* never closed", "unterminated /* comment"},
  };
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const std::string name = "refused" + std::to_string(k) + ".geo";
    const std::string path = (test::scratch_folder() / name).string();
    const std::string message = refusal(name, "h = 0.5;\n" + cases[k].text + "\n");
    EXPECT_EQ(message.rfind(path + ":2: ", 0), 0u) << cases[k].text << " -> " << message;
    EXPECT_NE(message.find(cases[k].expected), std::string::npos) << cases[k].text << " -> " << message;
  }
  EXPECT_FALSE(fs::exists(marker));
}

TEST(GeoScriptCheck, GeometryScriptsPass) {
  for (const char* shipped : {"/configs/domains/l_shape.geo", "/configs/domains/g1_pentagon_quads.geo",
                              "/tests/support/data/square_groups.geo"})
    EXPECT_NO_THROW(check_geo_script(source_dir + shipped, {source_dir})) << shipped;
  test::scratch_file("part.geo", "Point(newp) = {0.5, 0.5, 0, h};\n");
  const std::string path =
      test::scratch_file("rich.geo",
                         "// SystemCall in a comment, /* Save */ and strings are not code\n"
                         "/* Exit; */\n"
                         "DefineConstant[ h = {0.25, Name \"mesh size\"} ];\n"
                         "n = 4; Printf(\"SystemCall %g\", n);\n"
                         "Macro Corner\n  Point(newp) = {x, y, 0, h};\nReturn\n"
                         "For i In {0:n-1}\n  x = i / n; y = 0; Call Corner;\nEndFor\n"
                         "If (n > 2)\n  Mesh.RecombineAll = 1;\nElse\n  Mesh.Algorithm = 6;\nEndIf\n"
                         "Point(100) = {0, 1, 0, h}; Point(101) = {1, 1, 0, h}; Point(102) = {1, 0, 0, h};\n"
                         "Line(1) = {1, 102}; Line(2) = {102, 101}; Line(3) = {101, 100}; Line(4) = {100, 1};\n"
                         "Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};\n"
                         "Include \"part.geo\";\n"
                         "Field[1] = Distance; Field[1].PointsList = {1}; Field[2] = Threshold; Field[2].InField = 1;\n"
                         "Background Field = 2;\n"
                         "Transfinite Curve{1} = 5; Recombine Surface{1};\n"
                         "Physical Curve(\"bottom\") = {1}; Physical Surface(\"all\") = {1};\n"
                         "Geometry.Tolerance = 1e-9; Mesh.ElementOrder = 1; Mesh.MeshSizeFactor = 1;\n"
                         "list[] = {1:10}; list[] += 11; k++; k -= 2;\n"
                         "Point(103) = {0.5, 0.5, 0, h}; Point{103} In Surface{1};\n"
                         "Delete { Point{100}; }\n");
  EXPECT_NO_THROW(check_geo_script(path, {test::scratch_folder()}));
}

/// geo_script_largest_point_size of a script written to the scratch folder.
double largest_size(const std::string& name, const std::string& text) {
  return geo_script_largest_point_size(test::scratch_file(name, text), {test::scratch_folder()});
}

TEST(GeoScriptSizes, TheLargestPointSizeAtTheEndOfTheScript) {
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(largest_size("s1.geo", "Point(1) = {0, 0, 0, 0.1};\nPoint(2) = {1, 0, 0, 0.25};\n"), 0.25);
  EXPECT_EQ(largest_size("s2.geo", "lc = 1e-3 / 4;\nPoint(1) = {0, 0, 0, lc};\nPoint(2) = {1, 0, 0, 2 * lc};\n"), 5e-4);
  // MeshSize and Characteristic Length replace the sizes of the points they list (ids and ranges).
  EXPECT_EQ(largest_size("s3.geo", "Point(1) = {0, 0, 0, 0.5};\nPoint(2) = {1, 0, 0, 0.5};\nMeshSize {1, 2} = 1e-7;\n"), 1e-7);
  EXPECT_EQ(largest_size("s4.geo", "Point(1) = {0, 0, 0, 0.5};\nPoint(2) = {1, 0, 0, 0.5};\n"
                                   "Characteristic Length {1:2} = 1e-6;\n"), 1e-6);
  EXPECT_EQ(largest_size("s5.geo", "Point(1) = {0, 0, 0, 0.5};\nPoint(2) = {1, 0, 0, 0.5};\nMeshSize {1} = 1e-6;\n"), 0.5);
  // A point whose id is a loop's keeps its size in the bound; one without a size, or with a size
  // not evaluated here (a function call), means no bound.
  EXPECT_EQ(largest_size("s6.geo", "For i In {1:3}\n  Point(i) = {i, 0, 0, 0.2};\nEndFor\n"), 0.2);
  EXPECT_EQ(largest_size("s7.geo", "Point(1) = {0, 0, 0, 0.1};\nPoint(2) = {1, 0, 0};\n"), inf);
  EXPECT_EQ(largest_size("s8.geo", "Point(1) = {0, 0, 0, Sqrt(2) / 10};\n"), inf);
  EXPECT_EQ(largest_size("s9.geo", "SetFactory(\"OpenCASCADE\");\nRectangle(1) = {0, 0, 0, 1, 1};\n"), inf);
  // The option file "<file>.opt" runs after the script.
  test::scratch_file("s10.geo.opt", "MeshSize {1} = 1e-9;\n");
  EXPECT_EQ(largest_size("s10.geo", "Point(1) = {0, 0, 0, 0.5};\n"), 1e-9);
}

TEST(GeoScriptCheck, IncludesAreCheckedInTurn) {
  test::scratch_file("bad_part.geo", "Point(1) = {0,0,0,1};\nSystemCall \"ls\";\n");
  const std::string message = refusal("includes_bad.geo", "Include \"bad_part.geo\";\n");
  EXPECT_EQ(message.rfind((test::scratch_folder() / "bad_part.geo").string() + ":2: 'SystemCall'", 0), 0u) << message;
  test::scratch_file("loop_a.geo", "Include \"loop_b.geo\";\n");
  test::scratch_file("loop_b.geo", "Include \"loop_a.geo\";\n");
  EXPECT_NE(
      refusal("loop_a.geo", "Include \"loop_b.geo\";\n").find("'loop_a.geo' includes itself (a cycle of Includes)"),
      std::string::npos);
  EXPECT_NE(refusal("missing_part.geo", "Include \"nowhere.geo\";\n").find("'nowhere.geo' is not a readable file"),
            std::string::npos);
  // A symbolic link inside the folder that points outside is outside.
  const fs::path link = test::scratch_folder() / "escape.geo";
  std::error_code ec;
  fs::remove(link, ec);
  fs::create_symlink("/etc/hostname", link);
  EXPECT_NE(refusal("via_link.geo", "Include \"escape.geo\";\n").find("is outside the folder"), std::string::npos);
}

TEST(GeoScriptCheck, TheOptionFileGmshRunsIsCheckedToo) {
  const std::string path = test::scratch_file("with_options.geo", "Point(1) = {0,0,0,1};\n");
  test::scratch_file("with_options.geo.opt", "Mesh.Algorithm = 6;\nSystemCall \"ls\";\n");
  try {
    check_geo_script(path, {test::scratch_folder()});
    ADD_FAILURE() << "not refused";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(path + ".opt:2: 'SystemCall'", 0), 0u) << e.what();
  }
  // A .msh with an option file beside it: the same check before Gmsh opens the mesh.
  const std::string msh = (test::scratch_folder() / "with_options.msh").string();
  fs::copy_file(source_dir + "/tests/support/data/square_groups.msh", msh, fs::copy_options::overwrite_existing);
  test::scratch_file("with_options.msh.opt", "Save \"/tmp/x.msh\";\n");
  try {
    read_mesh_file(msh);
    ADD_FAILURE() << "not refused";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(msh + ".opt:1: 'Save'", 0), 0u) << e.what();
  }
}

TEST(GeoScriptCheck, ReadMeshFileRefusesBeforeGmshRuns) {
  const fs::path marker = test::scratch_folder() / "ran";
  const std::string path =
      test::scratch_file("hostile.geo", "Point(1) = {0,0,0,1};\nSystemCall \"touch " + marker.string() + "\";\n");
  try {
    read_mesh_file(path);
    ADD_FAILURE() << "not refused";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(path + ":2: 'SystemCall' is not allowed", 0), 0u) << e.what();
  }
  EXPECT_FALSE(fs::exists(marker));
}

TEST(GeoScriptCheck, IgaRunExitsWithTwoAndRunsNothing) {
  const fs::path marker = test::scratch_folder() / "iga_run_marker";
  const std::string geo = test::scratch_file("cli.geo", "Exit;\nSystemCall \"touch " + marker.string() + "\";\n");
  const std::string config = test::scratch_file("cli.yaml",
                                                "problem: {pde: poisson, exact: \"x\", boundary: {all: dirichlet}}\n"
                                                "domain: {type: mesh_file, file: cli.geo}\nspace: {type: ws4}\n");
  const fs::path output = test::scratch_folder() / "cli_output";
  const std::string command = std::string(IGA_RUN_BINARY) + " -q -o " + output.string() + " " + config + " 2>" +
                              (test::scratch_folder() / "cli_stderr").string();
  const int status = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 2);
  std::ifstream err(test::scratch_folder() / "cli_stderr");
  const std::string text((std::istreambuf_iterator<char>(err)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find(geo + ":1: 'Exit' is not allowed"), std::string::npos) << text;
  EXPECT_FALSE(fs::exists(marker));
  EXPECT_FALSE(fs::exists(output));
}

}  // namespace
}  // namespace iga
