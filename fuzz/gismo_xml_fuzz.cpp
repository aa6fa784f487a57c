// libFuzzer target: the G+Smo XML geometry reader (tinyxml2 and our checks), the bilinear
// multipatch mesh built from it with its validation, and the single-patch path.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz/fuzz_support.hpp"
#include "mesh/gismo_xml.hpp"
#include "mesh/validate_planar_mesh.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  iga::fuzz::expect_input_error([&] {
    const iga::GismoMultiPatch mp = iga::parse_gismo_xml(text, "fuzz.xml");
    iga::fuzz::expect_input_error([&] { iga::single_gismo_patch(mp, "bspline"); });
    iga::fuzz::expect_input_error([&] {
      const iga::PlanarMesh mesh = iga::bilinear_patch_mesh(mp);
      iga::validate_planar_mesh(mesh, {true, true, "g1"});
    });
  });
  return 0;
}
