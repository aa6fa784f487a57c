#include "config/utf8.hpp"

#include <cstdio>

namespace iga {

std::optional<std::size_t> invalid_utf8_offset(std::string_view text) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  for (std::size_t i = 0; i < text.size();) {
    const unsigned char c = byte(i);
    if (c < 0x80) {
      ++i;
      continue;
    }
    // Length and the allowed range of the second byte (which excludes overlong forms, surrogates
    // and code points above U+10FFFF), as in the Unicode standard's table of well-formed sequences.
    std::size_t n = 0;
    unsigned char lo = 0x80, hi = 0xBF;
    if (c >= 0xC2 && c <= 0xDF) {
      n = 2;
    } else if (c >= 0xE0 && c <= 0xEF) {
      n = 3;
      if (c == 0xE0) lo = 0xA0;
      if (c == 0xED) hi = 0x9F;
    } else if (c >= 0xF0 && c <= 0xF4) {
      n = 4;
      if (c == 0xF0) lo = 0x90;
      if (c == 0xF4) hi = 0x8F;
    } else {
      return i;
    }
    if (i + n > text.size() || byte(i + 1) < lo || byte(i + 1) > hi) return i;
    for (std::size_t k = 2; k < n; ++k)
      if (byte(i + k) < 0x80 || byte(i + k) > 0xBF) return i;
    i += n;
  }
  return std::nullopt;
}

std::optional<std::size_t> control_character_offset(std::string_view text) {
  for (std::size_t i = 0; i < text.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c < 0x20 && c != '\t' && c != '\n' && c != '\r') return i;
  }
  return std::nullopt;
}

std::optional<std::string> wide_byte_order_mark(std::string_view text) {
  using namespace std::string_view_literals;
  // UTF-32LE's mark starts with UTF-16LE's: the longer ones are tried first.
  if (text.starts_with("\x00\x00\xFE\xFF"sv)) return "UTF-32BE";
  if (text.starts_with("\xFF\xFE\x00\x00"sv)) return "UTF-32LE";
  if (text.starts_with("\xFE\xFF"sv)) return "UTF-16BE";
  if (text.starts_with("\xFF\xFE"sv)) return "UTF-16LE";
  return std::nullopt;
}

std::string describe_byte(std::string_view text, std::size_t offset) {
  char hex[8];
  std::snprintf(hex, sizeof hex, "0x%02X", static_cast<unsigned>(static_cast<unsigned char>(text[offset])));
  return std::string("byte ") + hex;
}

}  // namespace iga
