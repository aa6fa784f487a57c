#pragma once
/// @file
/// UTF-8 validity of text from other people's files. Names and strings from a config or a mesh
/// file end up in summary.json (whose writer refuses text that is not UTF-8), VTK files and
/// messages; they are checked where they are read, so a bad byte is an input error naming its
/// place instead of a failure after the study.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace iga {

/// Offset of the first byte of `text` that does not start a well-formed UTF-8 sequence (a stray
/// continuation byte, a truncated sequence, an overlong form, a surrogate, a code point above
/// U+10FFFF, bytes C0, C1, F5..FF), or nullopt when the whole text is UTF-8.
std::optional<std::size_t> invalid_utf8_offset(std::string_view text);

/// Offset of the first C0 control character of `text` other than tab, line feed and carriage
/// return (NUL among them: a path or name holding one is cut short where it is used), or nullopt.
std::optional<std::size_t> control_character_offset(std::string_view text);

/// The encoding a byte-order mark at the start of `text` names when it is not UTF-8's ("UTF-16LE",
/// "UTF-32BE", ...), or nullopt (no mark, or UTF-8's).
std::optional<std::string> wide_byte_order_mark(std::string_view text);

/// "byte 0xFF": the byte of `text` at `offset`, for messages.
std::string describe_byte(std::string_view text, std::size_t offset);

}  // namespace iga
