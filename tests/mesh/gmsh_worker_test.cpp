// The Gmsh worker process as the second line of defence: hostile scripts handed to it directly
// (without the static script check) cannot run commands, write or read outside their folder,
// loop or allocate without end, or end the calling process; every failure is an InputError
// naming the file.

#include "tests/support/input_error.hpp"
#include "mesh/gmsh_worker.hpp"

#include <gtest/gtest.h>
#include <linux/landlock.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>

#include "config/errors.hpp"
#include "mesh/mesh_polygon.hpp"
#include "mesh/read_mesh_file.hpp"
#include "tests/support/scratch_files.hpp"

namespace iga {
namespace {

namespace fs = std::filesystem;

const std::string source_dir = IGA_SOURCE_DIR;

using test::input_error;

/// A .geo in the scratch folder, meshed by the worker with the static check bypassed.
GmshJob unchecked_geo(const std::string& name, const std::string& text, double seconds = 20.0) {
  GmshJob job;
  job.kind = GmshJob::mesh_geo;
  job.path = test::scratch_file(name, text);
  job.source = job.path;
  job.readable_folders = {test::scratch_folder().string()};
  job.limits.seconds = seconds;
  return job;
}

const std::string triangle_geo =
    "Point(1) = {0,0,0,0.5}; Point(2) = {1,0,0,0.5}; Point(3) = {0,1,0,0.5};\n"
    "Line(1) = {1,2}; Line(2) = {2,3}; Line(3) = {3,1};\n"
    "Curve Loop(1) = {1,2,3}; Plane Surface(1) = {1};\n";

/// Outcome of a job that may succeed or fail: the InputError message, or "" for a mesh.
std::string outcome(const GmshJob& job) {
  try {
    run_gmsh_job(job);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(GmshWorker, ShellCommandsDoNotRun) {
  const fs::path marker = test::scratch_folder() / "system_call_ran";
  for (const char* call : {"SystemCall", "System", "NonBlockingSystemCall"}) {
    const GmshJob job =
        unchecked_geo("system.geo", std::string(call) + " \"touch " + marker.string() + "\";\n" + triangle_geo);
    const std::string message = outcome(job);
    EXPECT_FALSE(fs::exists(marker)) << call << ": the command ran; " << message;
  }
}

TEST(GmshWorker, FilesAreNotWritten) {
  const fs::path inside = test::scratch_folder() / "saved_inside.msh";
  const fs::path outside = fs::temp_directory_path() / ("iga-gmsh-worker-save-" + std::to_string(::getpid()) + ".msh");
  const std::string text = triangle_geo + "Mesh 2;\nSave \"" + inside.string() + "\";\nSave \"" + outside.string() +
                           "\";\nPrintf(\"x\") > \"" + inside.string() + ".txt\";\nCreateDir \"" +
                           (test::scratch_folder() / "made").string() + "\";\n";
  outcome(unchecked_geo("save.geo", text));
  EXPECT_FALSE(fs::exists(inside));
  EXPECT_FALSE(fs::exists(outside));
  EXPECT_FALSE(fs::exists(inside.string() + ".txt"));
  EXPECT_FALSE(fs::exists(test::scratch_folder() / "made"));
  std::error_code ec;
  fs::remove(outside, ec);
}

bool kernel_has_landlock() {
  return ::syscall(SYS_landlock_create_ruleset, nullptr, 0, LANDLOCK_CREATE_RULESET_VERSION) >= 1;
}

TEST(GmshWorker, FilesOutsideTheFolderAreNotRead) {
  if (!kernel_has_landlock()) GTEST_SKIP() << "no Landlock in this kernel (the static check still refuses)";
  const std::string message = outcome(unchecked_geo("passwd.geo", "Include \"/etc/passwd\";\n" + triangle_geo));
  EXPECT_EQ(message.find("root"), std::string::npos) << message;
  const std::string merged = outcome(unchecked_geo("merge.geo", "Merge \"/etc/hostname\";\n" + triangle_geo));
  EXPECT_EQ(merged.find("root"), std::string::npos) << merged;
}

TEST(GmshWorker, ExitEndsOnlyTheWorker) {
  const GmshJob job = unchecked_geo("exit.geo", triangle_geo + "Exit;\n");
  const std::string message = input_error([&] { run_gmsh_job(job); });
  EXPECT_EQ(message.rfind(job.path + ": gmsh ended without a mesh", 0), 0u) << message;
  // Abort ends the script, not Gmsh: the statements before it are meshed (here none).
  const GmshJob aborting = unchecked_geo("abort.geo", "Abort;\n" + triangle_geo);
  EXPECT_EQ(input_error([&] { run_gmsh_job(aborting); }),
            aborting.path +
                ": the mesh has no triangles or quadrilaterals (no meshed surface: a .geo needs a Plane Surface, a "
                ".msh its 2D elements)");
}

TEST(GmshWorker, EndlessLoopsEndAtTheTimeLimit) {
  const auto start = std::chrono::steady_clock::now();
  const GmshJob job = unchecked_geo("loop.geo", "For i In {1:1e12}\n  x = i;\nEndFor\n" + triangle_geo, 2.0);
  const std::string message = input_error([&] { run_gmsh_job(job); });
  EXPECT_EQ(message.rfind(job.path + ": gmsh", 0), 0u) << message;
  EXPECT_NE(message.find("time limit of 2 s"), std::string::npos) << message;
  // The worker is gone once the call returns (killed at the limit; a generous bound on the wait).
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(30));
  const GmshJob sleeping = unchecked_geo("sleep.geo", "Sleep 1000;\n" + triangle_geo, 1.0);
  EXPECT_NE(input_error([&] { run_gmsh_job(sleeping); }).find("time limit"), std::string::npos);
}

TEST(GmshWorker, MemoryEndsAtTheLimit) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "under AddressSanitizer the worker sets no address-space limit (the shadow memory needs terabytes)";
#endif
  // A list of 1e10 numbers (80 GB) against a limit of 1 GiB.
  GmshJob job = unchecked_geo("big_list.geo", "x[] = {1:1e10};\n" + triangle_geo, 60.0);
  job.limits.memory_bytes = std::size_t{1} << 30;
  const std::string message = input_error([&] { run_gmsh_job(job); });
  // Gmsh catches most failed allocations itself ("Out of memory"); the worker's own message covers
  // the rest ("needed more memory than the limit of 1 GiB").
  EXPECT_EQ(message.rfind(job.path + ": gmsh", 0), 0u) << message;
  EXPECT_NE(message.find("emory"), std::string::npos) << message;
}

TEST(GmshWorker, GmshMeshingErrorsAreInputErrors) {
  // An open curve loop, a self-intersecting loop and huge coordinates made Gmsh throw inside its
  // OpenMP region, which aborted the whole process.
  const std::vector<std::pair<std::string, std::string>> scripts = {
      {"open_loop.geo",
       "Point(1) = {0,0,0,0.1}; Point(2) = {1,0,0,0.1}; Point(3) = {1,1,0,0.1}; Point(4) = {0,1,0,0.1};\n"
       "Line(1) = {1,2}; Line(2) = {2,3}; Line(3) = {3,4};\n"
       "Curve Loop(1) = {1,2,3}; Plane Surface(1) = {1};\n"},
      {"bow_tie.geo",
       "Point(1) = {0,0,0,0.1}; Point(2) = {1,1,0,0.1}; Point(3) = {1,0,0,0.1}; Point(4) = {0,1,0,0.1};\n"
       "Line(1) = {1,2}; Line(2) = {2,3}; Line(3) = {3,4}; Line(4) = {4,1};\n"
       "Curve Loop(1) = {1,2,3,4}; Plane Surface(1) = {1};\n"},
      {"huge.geo",
       "Point(1) = {0,0,0,1}; Point(2) = {1e300,0,0,1}; Point(3) = {0,1e300,0,1};\n"
       "Line(1) = {1,2}; Line(2) = {2,3}; Line(3) = {3,1};\n"
       "Curve Loop(1) = {1,2,3}; Plane Surface(1) = {1};\n"},
  };
  for (const auto& [name, text] : scripts) {
    const GmshJob job = unchecked_geo(name, text, 10.0);
    const std::string message = outcome(job);
    // Gmsh aborts on the first two (its error is thrown inside an OpenMP region): the worker ends,
    // the caller reports it. The third Gmsh would mesh for ever: the element estimate refuses it
    // before meshing (its points' size 1 on a triangle of side 1e300).
    if (name == "huge.geo") {
      EXPECT_EQ(message.rfind(job.path + ": the script's mesh sizes (largest point size 1,", 0), 0u) << message;
      EXPECT_NE(message.find("far more than the limit of"), std::string::npos) << message;
      continue;
    }
    EXPECT_EQ(message.rfind(job.path + ": gmsh ", 0), 0u) << message;
    if (name == "open_loop.geo")
      EXPECT_NE(message.find("not to be forming a closed loop"), std::string::npos) << message;
  }
  // The same scripts through read_mesh_file (static check, then the worker): an InputError or a mesh.
  MeshFileOptions quick;
  quick.limits.seconds = 10.0;
  for (const auto& [name, text] : scripts) {
    const std::string path = test::scratch_file(name, text);
    try {
      read_mesh_file(path, quick);
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()).rfind(path + ": ", 0), 0u) << e.what();
    }
  }
}

TEST(GmshWorker, MeshSizeIsCheckedBeforeMeshing) {
  const std::string l_shape = source_dir + "/configs/domains/l_shape.geo";
  const auto start = std::chrono::steady_clock::now();
  const std::string message = input_error([&] { read_mesh_file(l_shape, {1e-9, false}); });
  // Bounding box 2 x 2 = 4: 4 / (sqrt(3)/4 * 1e-18) = 9.2e18 triangles.
  EXPECT_EQ(message.rfind(l_shape + ": mesh size 1e-09 on an area of 4 gives about 9.2376e+18 triangles", 0), 0u)
      << message;
  EXPECT_NE(message.find("more than the limit of 2e+06 elements"), std::string::npos) << message;
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(30));
  // A raised limit lets a finer mesh through: h = 0.02 on the L-shape (estimate 4 / 1.73e-4 = 23 094).
  MeshFileOptions small{0.02, false};
  small.limits.max_elements = 1e4;
  EXPECT_NE(input_error([&] {
              read_mesh_file(l_shape, small);
            }).find("more than the limit of 10000"),
            std::string::npos);
  // Polygons: the exact area (3 x 1 = 3) gives 3 / (sqrt(3)/4 * 1e-18) = 6.9282e18.
  using V = Eigen::Vector2d;
  const PolygonDomain strip{{V(0, 0), V(3, 0), V(3, 1), V(0, 1)}, {}};
  EXPECT_EQ(input_error([&] { mesh_polygon(strip, 1e-9, false, "cfg.yaml:4:3: domain"); }),
            "cfg.yaml:4:3: domain: mesh size 1e-09 on an area of 3 gives about 6.9282e+18 triangles, more than the "
            "limit of 2e+06 elements (use a larger mesh size, or raise limits.max_elements in the config)");
  const PolygonDomain nan_vertex{{V(0, 0), V(std::nan(""), 0), V(0, 1)}, {}};
  EXPECT_EQ(input_error([&] { mesh_polygon(nan_vertex, 0.1, false, "polygon"); }),
            "polygon: outer vertex 2 (nan, 0) is not finite");
}

TEST(GmshWorker, GeometryFeaturesWorkInsideTheConfinement) {
  // OpenCASCADE shapes, a Boolean difference and an Include from the same folder.
  test::scratch_file("width.geo", "w = 2;\n");
  const std::string path = test::scratch_file("occ.geo",
                                              "SetFactory(\"OpenCASCADE\");\n"
                                              "Include \"width.geo\";\n"
                                              "Rectangle(1) = {0, 0, 0, w, 1};\n"
                                              "Disk(2) = {0.5, 0.5, 0, 0.2};\n"
                                              "BooleanDifference{ Surface{1}; Delete; }{ Surface{2}; Delete; }\n");
  const PlanarMesh m = read_mesh_file(path, {0.1, false});
  double area = 0.0;
  for (int c = 0; c < static_cast<int>(m.cells.size()); ++c) area += 0.5 * twice_signed_area(m, c);
  // 2 x 1 minus a disc of radius r = 0.2 whose boundary becomes chords of length <= h = 0.1: the
  // inscribed polygon leaves at most (2/3) (2 pi r) h²/(8 r) = pi h²/6 of the disc in the mesh.
  const double exact = 2.0 - M_PI * 0.04;
  EXPECT_GE(area, exact - 1e-12);
  EXPECT_LE(area, exact + M_PI * 0.01 / 6.0);
}

TEST(GmshWorker, TheCallerSurvivesAndGmshStillWorks) {
  // After every failure above in this process, a normal file still meshes.
  const std::string l_shape = source_dir + "/configs/domains/l_shape.geo";
  outcome(unchecked_geo("exit_again.geo", "Exit;\n"));
  const PlanarMesh m = read_mesh_file(l_shape, {0.25, false});
  double area = 0.0;
  for (int c = 0; c < static_cast<int>(m.cells.size()); ++c) area += 0.5 * twice_signed_area(m, c);
  EXPECT_NEAR(area, 3.0, 1e-12);
}

}  // namespace
}  // namespace iga
