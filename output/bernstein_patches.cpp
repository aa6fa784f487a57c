#include "output/bernstein_patches.hpp"

#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "config/errors.hpp"

namespace iga {

namespace {

constexpr const char* format_name = "iga-run-bezier-triangles";

struct Lines {
  std::istream& in;
  std::string source;
  int line = 0;

  [[noreturn]] void fail(const std::string& message) const {
    throw InputError(source + ":" + std::to_string(line) + ": " + message);
  }
  /// The next non-comment, non-blank line as a stream.
  std::istringstream next(const char* expected) {
    for (std::string text; std::getline(in, text);) {
      ++line;
      const auto start = text.find_first_not_of(" \t\r");
      if (start == std::string::npos || text[start] == '#') continue;
      return std::istringstream(text);
    }
    ++line;
    fail(std::string("the file ends where ") + expected + " was expected");
  }
  template <class T>
  T keyword_value(const std::string& keyword) {
    std::istringstream s = next(keyword.c_str());
    std::string word;
    T value{};
    if (!(s >> word >> value) || word != keyword) fail("expected '" + keyword + " <value>'");
    return value;
  }
};

}  // namespace

void write_bernstein_patches(std::ostream& out, const SurfacePatches& surface, const std::string& comment) {
  if (!comment.empty()) out << "# " << comment << "\n";
  const int degree = surface.patches.empty() ? 0 : surface.patches.front().degree;
  out << format_name << " 1\ndegree " << degree << "\npatches " << surface.patches.size() << "\n";
  out << std::setprecision(std::numeric_limits<double>::max_digits10);
  for (std::size_t n = 0; n < surface.patches.size(); ++n) {
    if (surface.patches[n].degree != degree)
      throw std::logic_error("write_bernstein_patches: the patches must all have one degree");
    const auto& v = surface.vertices[n];
    out << "patch " << n << " " << v[0] << " " << v[1] << " " << v[2] << "\n";
    for (const auto& b : surface.patches[n].control) out << b[0] << " " << b[1] << " " << b[2] << "\n";
  }
}

void write_bernstein_patches_file(const SurfacePatches& surface, const std::string& filename,
                                  const std::string& comment) {
  std::ofstream out(filename);
  if (!out) throw std::runtime_error("cannot write " + filename);
  write_bernstein_patches(out, surface, comment);
  out.close();
  if (!out) throw std::runtime_error("cannot write " + filename);
}

SurfacePatches read_bernstein_patches(std::istream& in, const std::string& source) {
  Lines lines{in, source};
  {
    std::istringstream s = lines.next("the header");
    std::string name;
    int version = 0;
    if (!(s >> name >> version) || name != format_name || version != 1)
      lines.fail(std::string("expected the header '") + format_name + " 1'");
  }
  const int degree = lines.keyword_value<int>("degree");
  if (degree < 0 || degree > 30) lines.fail("degree must be in 0..30");
  const long count = lines.keyword_value<long>("patches");
  if (count < 0) lines.fail("negative patch count");
  SurfacePatches surface;
  for (long n = 0; n < count; ++n) {
    std::istringstream s = lines.next("a 'patch' line");
    std::string word;
    long index = -1;
    std::array<int, 3> v{};
    if (!(s >> word >> index >> v[0] >> v[1] >> v[2]) || word != "patch" || index != n)
      lines.fail("expected 'patch " + std::to_string(n) + " i j k'");
    BezierTriangle patch;
    patch.degree = degree;
    for (int c = 0; c < bezier_count(degree); ++c) {
      std::istringstream p = lines.next("a control point");
      Eigen::Vector3d b;
      if (!(p >> b[0] >> b[1] >> b[2])) lines.fail("expected a control point 'x y z'");
      patch.control.push_back(b);
    }
    surface.patches.push_back(std::move(patch));
    surface.vertices.push_back(v);
  }
  return surface;
}

}  // namespace iga
