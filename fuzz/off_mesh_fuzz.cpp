// libFuzzer target: the OFF reader and the planar mesh validation (read-only, no Gmsh).
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz/text_mesh_support.hpp"
#include "mesh/read_text_meshes.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  iga::fuzz::read_and_validate(std::string(reinterpret_cast<const char*>(data), size), iga::read_off_mesh, "fuzz.off");
  return 0;
}
