#include "config/companion_file.hpp"

#include <stdexcept>
#include <system_error>

namespace iga {

namespace fs = std::filesystem;

fs::path find_companion_file(const std::string& what, const std::string& name, const std::vector<std::string>& relative,
                             const std::vector<std::string>& absolute) {
  std::error_code ec;
  const fs::path exe_dir = fs::read_symlink("/proc/self/exe", ec).parent_path();
  std::vector<fs::path> candidates;
  if (!ec) {
    candidates.push_back(exe_dir / name);
    for (const std::string& r : relative) candidates.push_back(exe_dir / r / name);
  }
  for (const std::string& a : absolute) candidates.push_back(a);
  for (const fs::path& c : candidates)
    if (fs::is_regular_file(c, ec)) return c;
  std::string places = "next to the executable";
  for (const std::string& r : relative) places += ", in " + r + "/ from it";
  for (const std::string& a : absolute) places += " or at " + a;
  throw std::runtime_error("cannot find " + what + " '" + name + "' " + places);
}

}  // namespace iga
