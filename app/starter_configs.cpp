#include "app/starter_configs.hpp"

#include <sstream>

#include "config/config_node.hpp"
#include "config/errors.hpp"

namespace iga {

namespace {

std::string trimmed(const std::string& s) {
  const auto b = s.find_first_not_of(" \t"), e = s.find_last_not_of(" \t\r");
  return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

std::string comma_separated(const std::vector<std::string>& words) {
  std::string out;
  for (const std::string& w : words) out += (out.empty() ? "" : ", ") + w;
  return out;
}

}  // namespace

std::vector<StarterConfig> starter_configs(std::string_view page) {
  std::vector<std::string> lines;
  std::istringstream in{std::string(page)};
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  std::vector<StarterConfig> out;
  for (size_t i = 0; i < lines.size(); ++i) {
    if (trimmed(lines[i]) != "```yaml starter") continue;
    StarterConfig starter;
    starter.line = static_cast<int>(i + 1);
    size_t k = i + 1;
    for (; k < lines.size() && trimmed(lines[k]).rfind("```", 0) != 0; ++k) starter.yaml += lines[k] + "\n";
    const ConfigNode root =
        ConfigNode::load_string(starter.yaml, "docs/configuration.md:" + std::to_string(starter.line));
    starter.space = root["space"]["type"].as_string();
    starter.domain = root["domain"]["type"].as_string();
    out.push_back(std::move(starter));
    i = k;
  }
  return out;
}

std::string starter_config_text(const std::string& space, const std::string& domain) {
  const std::vector<StarterConfig> starters = starter_configs(configuration_reference_page());
  std::vector<std::string> spaces, domains;
  const StarterConfig* found = nullptr;
  for (const StarterConfig& s : starters) {
    if (spaces.empty() || spaces.back() != s.space) spaces.push_back(s.space);
    if (s.space != space) continue;
    domains.push_back(s.domain);
    if (!found && (domain.empty() || s.domain == domain)) found = &s;
  }
  if (domains.empty()) {
    const std::string near = nearest_word(space, spaces);
    throw InputError("new: no space type '" + space + "'" + (near.empty() ? "" : " (did you mean '" + near + "'?)") +
                     "; the space types: " + comma_separated(spaces));
  }
  if (!found)
    throw InputError("new: space " + space + " has no starting config on domain type '" + domain +
                     "'; its domain types: " + comma_separated(domains));
  std::ostringstream out;
  out << "# A starting config: space " << found->space << " on a domain of type " << found->domain
      << " (iga-run new " << found->space << " " << found->domain << ").\n"
      << "# Save it (iga-run new ... > my.yaml), run it (iga-run my.yaml) and change it: every key is\n"
      << "# in docs/configuration.md, which shows this config among its complete examples.\n"
      << found->yaml;
  return out.str();
}

}  // namespace iga
