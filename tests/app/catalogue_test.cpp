/// @file
/// `iga-run --list` against the builders: every space type the factory builds has an entry, and
/// each entry names exactly the domain types and built-in layouts its builder builds on. What a
/// builder accepts is read from its own refusal of an unknown value ("expected one of ..."), so a
/// domain type or layout added to a builder and not to its entry (or the other way) fails here.

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <regex>
#include <string>
#include <vector>

#include "app/catalogue.hpp"
#include "config/config_node.hpp"
#include "config/errors.hpp"
#include "spaces/space_factory.hpp"

namespace iga {
namespace {

const std::string kUnknown = "zz_unknown";

/// The smallest space block of each type that gets its builder as far as reading the domain.
const std::map<std::string, std::string> kSpaceBlock = {
    {"bspline", "{type: bspline, degree: 2}"}, {"ws4", "{type: ws4}"},
    {"tmesh", "{type: tmesh, n: 3}"},          {"g1", "{type: g1, degree: 5}"},
    {"g1_4split", "{type: g1_4split, degree: 5}"}, {"surface", "{type: surface, degree: 2}"}};

/// The values the builder accepts at `place` (e.g. "domain.type"), from its refusal of kUnknown
/// there: building `domain` and `space` must fail at `place` with "expected one of ...".
std::vector<std::string> accepted_at(const std::string& place, const std::string& domain, const std::string& space) {
  const ConfigNode root = ConfigNode::load_string("domain: " + domain + "\nspace: " + space + "\n");
  std::string message;
  try {
    make_space(root["domain"], root["space"], 0);
  } catch (const InputError& e) {
    message = e.what();
  }
  static const std::regex choices("expected one of (.*), got '" + kUnknown + "'");
  std::smatch m;
  const std::string at = ": " + place + ": ";
  if (message.find(at) == std::string::npos || !std::regex_search(message, m, choices)) {
    ADD_FAILURE() << "domain " << domain << ", space " << space << ": expected a refusal of '" << kUnknown << "' at "
                  << place << ", got: " << (message.empty() ? "no error" : message);
    return {};
  }
  static const std::regex quoted("'([^']*)'");
  std::vector<std::string> words;
  const std::string list = m[1];
  for (auto it = std::sregex_iterator(list.begin(), list.end(), quoted); it != std::sregex_iterator(); ++it)
    words.push_back((*it)[1]);
  return words;
}

std::vector<std::string> domain_types(const SpaceCatalogueEntry& entry) {
  std::vector<std::string> types;
  for (const DomainFamily& d : entry.domains) types.push_back(d.type);
  return types;
}

TEST(Catalogue, HasAnEntryForEverySpaceTheFactoryBuilds) {
  std::vector<std::string> listed;
  for (const SpaceCatalogueEntry& entry : space_catalogue()) {
    listed.push_back(entry.type);
    EXPECT_FALSE(entry.description.empty()) << entry.type;
    EXPECT_FALSE(entry.domains.empty()) << entry.type;
  }
  EXPECT_EQ(listed, space_types());
  EXPECT_EQ(accepted_at("space.type", "{type: rectangle}", "{type: " + kUnknown + "}"), space_types());
  EXPECT_EQ(kSpaceBlock.size(), space_types().size()) << "a probe block for every space type";
}

TEST(Catalogue, NamesExactlyTheDomainTypesEachBuilderAccepts) {
  for (const SpaceCatalogueEntry& entry : space_catalogue()) {
    ASSERT_TRUE(kSpaceBlock.count(entry.type)) << entry.type;
    EXPECT_EQ(domain_types(entry), accepted_at("domain.type", "{type: " + kUnknown + "}", kSpaceBlock.at(entry.type)))
        << entry.type;
  }
}

/// The InputError building `domain` and `space` at level 0 gives, or "" when it builds.
std::string build_error(const std::string& domain, const std::string& space) {
  const ConfigNode root = ConfigNode::load_string("domain: " + domain + "\nspace: " + space + "\n");
  try {
    make_space(root["domain"], root["space"], 0);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(Catalogue, NamesTheBuiltInLayoutsEachSpaceIsBuiltOn) {
  // Every name the builder takes is listed, in its order, unless the builder refuses to build on
  // it (g1_4split reads every g1 layout's name and refuses those with triangles).
  int families = 0, refused = 0;
  for (const SpaceCatalogueEntry& entry : space_catalogue())
    for (const DomainFamily& d : entry.domains) {
      if (d.builtin_key.empty()) {
        EXPECT_TRUE(d.builtins.empty()) << entry.type << " on " << d.type;
        continue;
      }
      ++families;
      const std::string block = kSpaceBlock.at(entry.type);
      auto domain = [&](const std::string& name) { return "{type: " + d.type + ", " + d.builtin_key + ": " + name + "}"; };
      std::vector<std::string> taken;
      for (const std::string& name : accepted_at("domain." + d.builtin_key, domain(kUnknown), block)) {
        if (std::find(d.builtins.begin(), d.builtins.end(), name) != d.builtins.end()) {
          taken.push_back(name);
          continue;
        }
        ++refused;
        EXPECT_NE(build_error(domain(name), block), "") << entry.type << " on " << d.type << " " << name
                                                          << " builds but is not listed";
      }
      EXPECT_EQ(taken, d.builtins) << entry.type << " on " << d.type << ": listed names its builder does not take";
    }
  // g1 and g1_4split on multipatch, g1_4split and surface on surface, bspline on surface_patch
  // (shapes); g1_4split refuses the three g1 layouts with triangles (4t_crisscross, 4t_star, 2q2t_square).
  EXPECT_EQ(families, 5);
  EXPECT_EQ(refused, 3);
}

TEST(Catalogue, ListingShowsEveryEntry) {
  const std::string text = catalogue_text();
  for (const SpaceCatalogueEntry& entry : space_catalogue()) {
    EXPECT_NE(text.find("  " + entry.type + " "), std::string::npos) << entry.type;
    EXPECT_NE(text.find(entry.description + "\n"), std::string::npos) << entry.type;
    for (const DomainFamily& d : entry.domains) {
      EXPECT_NE(text.find("    " + d.type + " "), std::string::npos) << d.type;
      EXPECT_NE(text.find(d.keys + "\n"), std::string::npos) << d.keys;
      for (const std::string& name : d.builtins) EXPECT_NE(text.find(name), std::string::npos) << name;
    }
  }
}

}  // namespace
}  // namespace iga
