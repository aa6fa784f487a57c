#pragma once
/// @file
/// Line-by-line reading of the text mesh formats (OBJ, OFF), with errors that name file and line.

#include <istream>
#include <string>
#include <vector>

namespace iga {

/// Whitespace-separated tokens of a line, a '#' comment dropped.
std::vector<std::string> tokens_of(const std::string& line);

/// Reads the non-empty lines of `in`, counting lines for messages "SOURCE:LINE: ...".
struct TextLineReader {
  std::istream& in;
  std::string source;
  int line = 0;

  /// Throws InputError "source:line: message".
  [[noreturn]] void fail(const std::string& message) const;
  /// Next line with tokens; false at the end of the input.
  bool next(std::vector<std::string>& tokens);
  /// A finite number (NaN and infinities are input errors).
  double number(const std::string& token) const;
  long integer(const std::string& token) const;
  /// 0-based position of a 1-based (or negative, counted from the end) OBJ index into a list of
  /// `count` items named `what`.
  int obj_index(const std::string& token, long count, const char* what) const;
};

}  // namespace iga
