#include "mesh/stl_structure_check.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <vector>

#include "config/config_node.hpp"
#include "config/errors.hpp"
#include "mesh/text_line_reader.hpp"

namespace iga {

namespace {

constexpr std::uintmax_t header_bytes = 84, facet_bytes = 50;

void check_count(double count, const MeshLimits& limits, const std::string& path) {
  if (count > limits.max_elements)
    throw InputError(path + ": the STL file has " + format_number(count) + " triangles, more than the limit of " +
                     format_number(limits.max_elements));
}

void check_binary(const std::string& path, std::uint32_t count, const MeshLimits& limits) {
  check_count(count, limits, path);
  std::ifstream in(path, std::ios::binary);
  in.seekg(header_bytes);
  char facet[facet_bytes];
  for (std::uint32_t f = 0; f < count; ++f) {
    if (!in.read(facet, facet_bytes))
      throw InputError(path + ": the binary STL file ends inside triangle " + std::to_string(f + 1));
    for (int k = 3; k < 12; ++k) {  // the three vertices (the stored normal is not used)
      float x;
      std::memcpy(&x, facet + 4 * k, sizeof x);
      if (!std::isfinite(x))
        throw InputError(path + ": triangle " + std::to_string(f + 1) +
                         " of the binary STL file has a coordinate that is not a finite number");
    }
  }
}

void check_ascii(const std::string& path, const MeshLimits& limits) {
  std::ifstream in(path);
  TextLineReader reader{in, path};
  std::vector<std::string> t;
  const auto expect = [&](const std::vector<std::string>& words, std::size_t numbers, const std::string& what) {
    if (!reader.next(t)) reader.fail("the file ends where '" + what + "' was expected");
    if (t.size() != words.size() + numbers) reader.fail("expected '" + what + "'");
    for (std::size_t k = 0; k < words.size(); ++k)
      if (t[k] != words[k]) reader.fail("expected '" + what + "'");
    for (std::size_t k = words.size(); k < t.size(); ++k) reader.number(t[k]);  // finite numbers only
  };
  long long facets = 0;
  bool any_solid = false;
  while (reader.next(t)) {
    if (t[0] != "solid") reader.fail(any_solid ? "expected 'solid' or the end of the file" : "expected 'solid name'");
    any_solid = true;
    for (;;) {
      if (!reader.next(t)) reader.fail("the file ends inside a solid (no 'endsolid')");
      if (t[0] == "endsolid") break;
      if (t.size() != 5 || t[0] != "facet" || t[1] != "normal")
        reader.fail("expected 'facet normal nx ny nz' or 'endsolid'");
      for (int k = 2; k < 5; ++k) reader.number(t[k]);
      expect({"outer", "loop"}, 0, "outer loop");
      for (int v = 0; v < 3; ++v) expect({"vertex"}, 3, "vertex x y z");
      expect({"endloop"}, 0, "endloop");
      expect({"endfacet"}, 0, "endfacet");
      check_count(static_cast<double>(++facets), limits, path);
    }
  }
  if (facets == 0) throw InputError(path + ": the STL file has no triangles");
}

}  // namespace

void check_stl_structure(const std::string& path, const MeshLimits& limits) {
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec) throw InputError(path + ": cannot read the STL file");
  std::ifstream in(path, std::ios::binary);
  char head[header_bytes] = {};
  in.read(head, header_bytes);
  if (in.gcount() == static_cast<std::streamsize>(header_bytes)) {
    std::uint32_t count;
    std::memcpy(&count, head + 80, sizeof count);
    if (size == header_bytes + facet_bytes * std::uintmax_t{count}) {
      if (count == 0) throw InputError(path + ": the STL file has no triangles");
      return check_binary(path, count, limits);
    }
  }
  if (std::strncmp(head, "solid", 5) != 0 || size < 5)
    throw InputError(path + ": neither binary STL (the size does not match 84 + 50 x the triangle count) nor ASCII "
                            "STL (no 'solid' at the start)");
  check_ascii(path, limits);
}

}  // namespace iga
