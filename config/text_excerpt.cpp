#include "config/text_excerpt.hpp"

namespace iga {

std::string printable_excerpt(std::string_view text) {
  std::string out;
  for (std::size_t i = 0; i < text.size() && i < kMaxExcerptBytes; ++i) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    out += c >= 0x20 && c < 0x7F ? static_cast<char>(c) : '?';
  }
  if (text.size() > kMaxExcerptBytes) out += "...";
  return out;
}

std::string quoted_excerpt(std::string_view text) {
  std::string out = "'" + printable_excerpt(text.substr(0, kMaxExcerptBytes)) + "'";
  if (text.size() > kMaxExcerptBytes) out += "...";
  return out;
}

}  // namespace iga
