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

}  // namespace
}  // namespace iga
