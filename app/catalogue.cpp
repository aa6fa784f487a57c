#include "app/catalogue.hpp"

#include <sstream>

#include "spaces/space_factory.hpp"

namespace iga {

namespace {

/// `name` padded to `width` columns (at least one space after it).
std::string padded(const std::string& name, std::size_t width) {
  return name + std::string(name.size() < width ? width - name.size() : 1, ' ');
}

std::string joined(const std::vector<std::string>& words) {
  std::string out;
  for (const std::string& w : words) out += (out.empty() ? "" : ", ") + w;
  return out;
}

}  // namespace

std::string catalogue_text() {
  std::ostringstream out;
  out << "space types (space.type), each with the domain types (domain.type) it is built on:\n";
  for (const SpaceCatalogueEntry& space : space_catalogue()) {
    out << "\n  " << padded(space.type, 12) << space.description << '\n';
    for (const DomainFamily& domain : space.domains) {
      out << "    " << padded(domain.type, 18) << domain.keys << '\n';
      if (!domain.builtins.empty())
        out << "    " << padded("", 18) << "built-in domain." << domain.builtin_key << ": " << joined(domain.builtins)
            << '\n';
    }
  }
  // A graph lifts the planar domain of any space, so it is listed once rather than under each.
  out << "\nand, for every space above on a planar domain:\n";
  for (const DomainFamily& domain : lifted_domain_families())
    out << "    " << padded(domain.type, 18) << domain.keys << '\n';
  return out.str();
}

}  // namespace iga
