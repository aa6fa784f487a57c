#pragma once
/// @file
/// Text from other people's files in messages. A reader that cannot parse a token quotes it, but
/// the file may be anything (a link to a private file, binary data): a message shows a short,
/// printable excerpt only, never control bytes that would rewrite the terminal or a log.

#include <cstddef>
#include <string>
#include <string_view>

namespace iga {

/// Longest excerpt quoted_excerpt shows, in bytes, before "...".
constexpr std::size_t kMaxExcerptBytes = 40;

/// `text` for a message, unquoted (e.g. an XML element name): as quoted_excerpt without the quotes.
std::string printable_excerpt(std::string_view text);

/// "'text'" for a message: bytes outside printable ASCII shown as '?', and text longer than
/// kMaxExcerptBytes cut there with "..." after it.
std::string quoted_excerpt(std::string_view text);

}  // namespace iga
