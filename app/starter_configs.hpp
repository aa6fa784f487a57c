#pragma once
/// @file
/// `iga-run new SPACE [DOMAIN]`: commented starting configs that run as they are. They are the
/// blocks of docs/configuration.md fenced as ```yaml starter (one per space and domain type); the
/// page is compiled into the program (cmake/embed_text.cmake), so the command prints exactly what
/// the reference shows and the two cannot disagree.

#include <string>
#include <string_view>
#include <vector>

namespace iga {

/// The text of docs/configuration.md as it was when the program was built (generated source).
std::string_view configuration_reference_page();

/// One starting config: its space type, its domain type and its YAML text (comments included).
struct StarterConfig {
  std::string space;
  std::string domain;
  std::string yaml;
  int line = 0;  ///< of the block's opening fence in docs/configuration.md, 1-based
};

/// Every ```yaml starter block of `page`, in page order (the first of a space is its default).
std::vector<StarterConfig> starter_configs(std::string_view page);

/// What `iga-run new space [domain]` prints: a header comment and the starter's YAML. An empty
/// `domain` takes the space's first starter. An unknown space or domain is an InputError naming the
/// argument and listing the choices.
std::string starter_config_text(const std::string& space, const std::string& domain);

}  // namespace iga
