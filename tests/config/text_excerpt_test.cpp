// Text from other people's files in messages: short, printable, quoted.

#include "config/text_excerpt.hpp"

#include <gtest/gtest.h>

#include <string>

namespace iga {
namespace {

using namespace std::string_literals;

TEST(TextExcerpt, ShortPrintableTextIsQuotedAsItIs) {
  EXPECT_EQ(quoted_excerpt("secret"), "'secret'");
  EXPECT_EQ(quoted_excerpt(""), "''");
  EXPECT_EQ(quoted_excerpt(std::string(kMaxExcerptBytes, 'a')), "'" + std::string(kMaxExcerptBytes, 'a') + "'");
}

TEST(TextExcerpt, LongTextIsCutAndControlBytesReplaced) {
  EXPECT_EQ(quoted_excerpt(std::string(1000, 'a')), "'" + std::string(kMaxExcerptBytes, 'a') + "'...");
  EXPECT_EQ(quoted_excerpt("a\x1b[2Jb\r\n\0c\x7f\xff"s), "'a?[2Jb???c?\?'");
  EXPECT_EQ(printable_excerpt("<tag\x07>"), "<tag?>");
  EXPECT_EQ(printable_excerpt(std::string(50, 'x')), std::string(kMaxExcerptBytes, 'x') + "...");
}

}  // namespace
}  // namespace iga
