// UTF-8 validity of text from other people's files, and a config that is not UTF-8 refused when it
// is read, naming the line, the column and the key of the bad byte.

#include "config/utf8.hpp"

#include <gtest/gtest.h>

#include <string>

#include "config/config_node.hpp"
#include "config/errors.hpp"

namespace iga {
namespace {

using namespace std::string_literals;

TEST(Utf8, WellFormedSequencesPass) {
  EXPECT_FALSE(invalid_utf8_offset(""));
  EXPECT_FALSE(invalid_utf8_offset("plain ASCII\n\t"));
  EXPECT_FALSE(invalid_utf8_offset("Dörfler −Δu ∂Ω 𝜑"));  // 2-, 3- and 4-byte sequences
  EXPECT_FALSE(invalid_utf8_offset("\xEF\xBB\xBFproblem:"));  // a byte order mark is UTF-8
  EXPECT_FALSE(invalid_utf8_offset("\xF4\x8F\xBF\xBF"));      // U+10FFFF, the last code point
  EXPECT_FALSE(invalid_utf8_offset("nul \0 inside"s));
}

TEST(Utf8, TheFirstBadByteIsFound) {
  EXPECT_EQ(invalid_utf8_offset("ab\xFF"), 2u);           // never in UTF-8
  EXPECT_EQ(invalid_utf8_offset("a\x80"), 1u);            // a continuation byte alone
  EXPECT_EQ(invalid_utf8_offset("\xC0\x80"), 0u);         // overlong NUL
  EXPECT_EQ(invalid_utf8_offset("\xE0\x80\xAF"), 0u);     // overlong '/'
  EXPECT_EQ(invalid_utf8_offset("x\xED\xA0\x80"), 1u);    // a UTF-16 surrogate
  EXPECT_EQ(invalid_utf8_offset("\xF4\x90\x80\x80"), 0u); // above U+10FFFF
  EXPECT_EQ(invalid_utf8_offset("ok \xE2\x82"), 3u);      // truncated at the end
  EXPECT_EQ(invalid_utf8_offset("\xC3(\xA9"), 0u);        // a lead byte without its continuation
}

std::string load_error(const std::string& text) {
  try {
    ConfigNode::load_string(text, "c.yaml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(Utf8, ConfigTextThatIsNotUtf8IsRefusedWhenRead) {
  // The byte's own line and column (1-based, in bytes), then the key path of the text that holds it.
  EXPECT_EQ(load_error("problem:\n  pde: poisson\noutput: {directory: \"results/a\xFF\"}\n"),
            "c.yaml:3:31: output.directory: byte 0xFF is not UTF-8 (a config is UTF-8 text)");
  EXPECT_EQ(load_error("problem:\n  ex\xC0\x80" "act: x\n"), "c.yaml:2:5: problem: byte 0xC0 is not UTF-8 (a config is UTF-8 text)");
  EXPECT_EQ(load_error("a: [1, \"\xE9\"]\n"), "c.yaml:1:9: a[1]: byte 0xE9 is not UTF-8 (a config is UTF-8 text)");
  EXPECT_EQ(load_error("# \xFE\na: 1\n"), "c.yaml:1:3: byte 0xFE is not UTF-8 (a config is UTF-8 text)");
  // A syntax error after the bad byte: the byte is the first problem named.
  EXPECT_EQ(load_error("a: [\n  b: \x80\n"), "c.yaml:2:6: byte 0x80 is not UTF-8 (a config is UTF-8 text)");
  EXPECT_EQ(load_error("a: \"Dörfler −Δu\"\n"), "");
}

TEST(Utf8, WideEncodingsAreRefusedAsAWhole) {
  // UTF-32LE with a surrogate in output.directory: yaml-cpp would decode it without a check.
  std::string utf32le = "\xFF\xFE\x00\x00"s;
  for (char32_t c : U"output: {directory: res") utf32le += std::string{char(c), '\0', '\0', '\0'};
  utf32le += "\x00\xD8\x00\x00}\x00\x00\x00\n\x00\x00\x00"s;
  EXPECT_EQ(load_error(utf32le),
            "c.yaml:1:1: the file starts with the byte-order mark of UTF-32LE: it is not UTF-8 text (a config is "
            "UTF-8 text; save it as UTF-8)");
  EXPECT_NE(load_error("\x00\x00\xFE\xFF\x00\x00\x00" "a"s).find("byte-order mark of UTF-32BE: it is not UTF-8 text"),
            std::string::npos);
  EXPECT_NE(load_error("\xFF\xFE" "a\x00:\x00 \x00" "1\x00"s).find("byte-order mark of UTF-16LE: it is not UTF-8 text"),
            std::string::npos);
  EXPECT_NE(load_error("\xFE\xFF\x00" "a\x00:\x00 \x00" "1"s).find("byte-order mark of UTF-16BE: it is not UTF-8 text"),
            std::string::npos);
  // UTF-16 without a mark has NUL bytes: refused as control characters, at the first.
  EXPECT_EQ(load_error("a\x00:\x00 \x00" "1\x00"s),
            "c.yaml:1:2: byte 0x00 is a control character (a config is text: tab, line feed and carriage return are "
            "the only ones allowed)");
  EXPECT_EQ(load_error("\xEF\xBB\xBF" "a: 1\n"), "");  // UTF-8's own mark is fine
}

TEST(Utf8, ControlCharactersAreRefusedWithTheirPlace) {
  EXPECT_EQ(control_character_offset("a\tb\r\nc"), std::nullopt);
  EXPECT_EQ(control_character_offset("ab\x1B"), 2u);
  // A raw NUL in a value: its line, column and key.
  EXPECT_EQ(load_error("problem: {pde: poisson}\noutput:\n  directory: a\x00" "b\n"s),
            "c.yaml:3:15: output.directory: byte 0x00 is a control character (a config is text: tab, line feed and "
            "carriage return are the only ones allowed)");
  EXPECT_EQ(load_error("# a \x07 bell\na: 1\n"s).rfind("c.yaml:1:5: byte 0x07 is a control character", 0), 0u);
  // Written as an escape, the file is clean but the value is not: the value's place and key.
  EXPECT_EQ(load_error("output:\n  directory: \"a\\0b\"\n"),
            "c.yaml:2:14: output.directory: byte 0x00, byte 2 of the text (written as an escape), is a control "
            "character (a config is text: tab, line feed and carriage return are the only ones allowed)");
  EXPECT_NE(load_error("names: [\"x\", \"\\e[31m\"]\n").find("c.yaml:1:14: names[1]: byte 0x1B, byte 1 of the text"),
            std::string::npos);
  // Aliases are walked once: a map holding itself, and an escape after it.
  EXPECT_NE(load_error("a: &x {b: *x, c: [*x, \"\\x01\"]}\n").find("c.yaml:1:23: a.c[1]: byte 0x01, byte 1 of"),
            std::string::npos);
  // Tabs, line breaks (also as escapes) and block scalars stay.
  EXPECT_EQ(load_error("a: \"x\\ty\\nz\"\r\nb: |\n  one\n  two\n"), "");
}

}  // namespace
}  // namespace iga
