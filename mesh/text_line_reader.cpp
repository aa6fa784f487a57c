#include "mesh/text_line_reader.hpp"

#include <charconv>
#include <cmath>
#include <sstream>

#include "config/errors.hpp"
#include "config/text_excerpt.hpp"

namespace iga {

std::vector<std::string> tokens_of(const std::string& line) {
  std::istringstream s(line.substr(0, line.find('#')));
  std::vector<std::string> tokens;
  for (std::string t; s >> t;) tokens.push_back(t);
  return tokens;
}

void TextLineReader::fail(const std::string& message) const {
  throw InputError(source + ":" + std::to_string(line) + ": " + message);
}

bool TextLineReader::next(std::vector<std::string>& tokens) {
  for (std::string text; std::getline(in, text);) {
    ++line;
    tokens = tokens_of(text);
    if (!tokens.empty()) return true;
  }
  return false;
}

double TextLineReader::number(const std::string& token) const {
  double x = 0.0;
  const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), x);
  if (error != std::errc() || end != token.data() + token.size()) fail("expected a number, got " + quoted_excerpt(token));
  if (!std::isfinite(x)) fail("the coordinate " + quoted_excerpt(token) + " is not finite");
  return x;
}

long TextLineReader::integer(const std::string& token) const {
  long i = 0;
  const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), i);
  if (error != std::errc() || end != token.data() + token.size()) fail("expected an integer, got " + quoted_excerpt(token));
  return i;
}

int TextLineReader::obj_index(const std::string& token, long count, const char* what) const {
  const long i = integer(token);
  const long id = i > 0 ? i - 1 : count + i;
  if (i == 0 || id < 0 || id >= count)
    fail(std::string(what) + " " + std::to_string(i) + " does not exist (" + std::to_string(count) +
         " so far; OBJ indices are 1-based)");
  return static_cast<int>(id);
}

}  // namespace iga
