// libFuzzer target: the surface mesh readers in 3D. Text starting with "OFF" goes to the OFF
// readers, anything else to the OBJ readers; each input is read both as a triangle surface
// (validated and given normals, as space: surface takes it) and as a quad surface (validated as
// the 4-split G1 space takes it).
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "fuzz/fuzz_support.hpp"
#include "geometry/triangle_surface_mesh.hpp"
#include "mesh/read_quad_surface_mesh.hpp"
#include "mesh/read_surface_mesh.hpp"
#include "mesh/validate_quad_surface.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const bool off = text.rfind("OFF", 0) == 0;
  iga::fuzz::expect_input_error([&] {
    std::istringstream in(text);
    const iga::SurfaceMeshFile file = off ? iga::read_off_surface(in, "fuzz.off") : iga::read_obj_surface(in, "fuzz.obj");
    iga::surface_mesh_from_file(file);
  });
  iga::fuzz::expect_input_error([&] {
    std::istringstream in(text);
    const iga::QuadSurfaceFile file =
        off ? iga::read_off_quad_surface(in, "fuzz.off") : iga::read_obj_quad_surface(in, "fuzz.obj");
    iga::validate_quad_surface(file);
  });
  return 0;
}
