#include "config/config_node.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <mutex>
#include <set>
#include <sstream>

#include "config/utf8.hpp"

namespace iga {

namespace {

/// "FILE:LINE:COL" with 1-based numbers (yaml-cpp counts from 0); just "FILE" without a place.
std::string location(const std::string& file, const YAML::Mark& mark) {
  if (mark.is_null() || mark.line < 0) return file;
  return file + ":" + std::to_string(mark.line + 1) + ":" + std::to_string(mark.column + 1);
}

/// How a node looks, for "expected X, got Y".
std::string describe(const YAML::Node& node) {
  switch (node.Type()) {
    case YAML::NodeType::Map:
      return "a map";
    case YAML::NodeType::Sequence:
      return "a sequence";
    case YAML::NodeType::Scalar:
      return "'" + node.Scalar() + "'";
    default:
      return "nothing";
  }
}

/// "in 'space'" or "at the top level", for key messages.
std::string in_map(const std::string& path) {
  return path.empty() ? std::string("at the top level") : "in '" + path + "'";
}

std::string quoted_list(const std::vector<std::string>& words) {
  std::string out;
  for (size_t i = 0; i < words.size(); ++i) out += (i ? ", '" : "'") + words[i] + "'";
  return out;
}

/// The whole text must be the number: from_chars ignores the locale and stops at the first bad
/// character, so partial matches like "2.5" read as int are caught by the end check.
template <class T>
bool parse_number(const std::string& text, T& value) {
  const char* begin = text.data();
  const char* end = begin + text.size();
  if (begin != end && *begin == '+') ++begin;  // YAML allows "+1"; from_chars does not
  auto [ptr, ec] = std::from_chars(begin, end, value);
  return ec == std::errc() && ptr == end && begin != end;
}

std::shared_ptr<const std::string> shared_name(const std::string& name) {
  return std::make_shared<const std::string>(name);
}

/// The declarations of check_keys and as_choice, for declared_config(). Recorded per call (a few
/// dozen calls per space built), never in a numerical loop.
struct DeclarationRegistry {
  std::mutex mutex;
  DeclaredConfig declared;
};

DeclarationRegistry& declaration_registry() {
  static DeclarationRegistry registry;
  return registry;
}

/// "space.refine_near[2].curve" -> "space.refine_near[].curve": one entry per place in the schema.
std::string schema_path(const std::string& path) {
  std::string out;
  bool in_index = false;
  for (const char c : path) {
    if (in_index && c != ']') continue;
    in_index = c == '[';
    out += c;
  }
  return out;
}

void declare(std::map<std::string, std::set<std::string>> DeclaredConfig::*table, const std::string& path,
             const std::vector<std::string>& words) {
  const std::string schema = schema_path(path);
  DeclarationRegistry& registry = declaration_registry();
  const std::lock_guard<std::mutex> lock(registry.mutex);
  (registry.declared.*table)[schema].insert(words.begin(), words.end());
}

/// Offset of the first byte of `text` a config may not hold: one that is not UTF-8, or a control
/// character other than tab, line feed and carriage return.
std::optional<std::size_t> bad_text_offset(std::string_view text) {
  const auto utf8 = invalid_utf8_offset(text), control = control_character_offset(text);
  if (utf8 && control) return std::min(*utf8, *control);
  return utf8 ? utf8 : control;
}

/// The first key or value under `node` whose text has a byte a config may not hold (bad_text_offset;
/// a double-quoted "\0" puts one there without the file holding it), and its key path. A collection
/// is walked once, at its first path: an alias repeats its anchor's node (same start), and walking
/// it again would be exponential for nested aliases and endless for a node that contains itself.
std::optional<std::pair<YAML::Node, std::string>> find_bad_text(const YAML::Node& node, const std::string& path,
                                                                std::set<int>& walked) {
  if (node.IsScalar()) {
    if (bad_text_offset(node.Scalar())) return std::make_pair(node, path);
  } else if ((node.IsSequence() || node.IsMap()) && walked.insert(node.Mark().pos).second) {
    if (node.IsSequence()) {
      for (std::size_t i = 0; i < node.size(); ++i)
        if (auto bad = find_bad_text(node[i], path + "[" + std::to_string(i) + "]", walked)) return bad;
    } else {
      for (const auto& kv : node) {
        const std::string key = kv.first.IsScalar() ? kv.first.Scalar() : std::string("?");
        const std::string child = path.empty() ? key : path + "." + key;
        if (auto bad = find_bad_text(kv.first, path, walked)) return bad;  // the key itself, at its map
        if (auto bad = find_bad_text(kv.second, child, walked)) return bad;
      }
    }
  }
  return std::nullopt;
}

/// Why byte `offset` of `text` (found by bad_text_offset) may not be in a config: " is ...".
std::string why_bad(std::string_view text, std::size_t offset) {
  if (static_cast<unsigned char>(text[offset]) < 0x20)
    return " is a control character (a config is text: tab, line feed and carriage return are the only ones allowed)";
  return " is not UTF-8 (a config is UTF-8 text)";
}

/// "LINE:COL" (1-based, columns in bytes) of byte `offset` of `text`.
std::string line_and_column(const std::string& text, std::size_t offset) {
  const auto line = 1 + std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(offset), '\n');
  const std::size_t start = offset == 0 ? std::string::npos : text.rfind('\n', offset - 1);
  const std::size_t column = start == std::string::npos ? offset + 1 : offset - start;
  return std::to_string(line) + ":" + std::to_string(column);
}

}  // namespace

ConfigNode::ConfigNode(YAML::Node node, std::string path, std::shared_ptr<const std::string> file,
                       std::shared_ptr<const YAML::Node> root, bool from_file)
    : node_(std::move(node)), path_(std::move(path)), file_(std::move(file)), root_(std::move(root)), from_file_(from_file) {}

ConfigNode ConfigNode::root() const { return ConfigNode(*root_, "", file_, root_, from_file_); }

ConfigNode ConfigNode::load_string(const std::string& text, const std::string& name) {
  const auto place = [&](std::size_t offset) {  // "c.yaml:3:7: "
    return name + ":" + line_and_column(text, offset) + ": ";
  };
  // yaml-cpp would decode UTF-16 and UTF-32 text without checking its code points (a surrogate or
  // U+110000 would reach folder names): such a file is refused as a whole.
  if (const auto encoding = wide_byte_order_mark(text))
    throw InputError(place(0) + "the file starts with the byte-order mark of " + *encoding +
                     ": it is not UTF-8 text (a config is UTF-8 text; save it as UTF-8)");
  // Text that is not UTF-8 would pass through yaml-cpp into messages, VTK files and summary.json
  // (whose writer throws on it, after the study), and a NUL cuts a path short where it is used:
  // refused here, at the first such key or value.
  const std::size_t bad = bad_text_offset(text).value_or(std::string::npos);
  const auto what = [&](std::size_t offset) { return describe_byte(text, offset) + why_bad(text, offset); };
  std::shared_ptr<const YAML::Node> root;
  try {
    root = std::make_shared<const YAML::Node>(YAML::Load(text));
  } catch (const YAML::ParserException& e) {
    if (bad != std::string::npos) throw InputError(place(bad) + what(bad));
    throw InputError(location(name, e.mark) + ": YAML syntax error: " + e.msg);
  } catch (const YAML::Exception& e) {
    if (bad != std::string::npos) throw InputError(place(bad) + what(bad));
    throw InputError(location(name, e.mark) + ": cannot read YAML: " + e.msg);
  }
  std::set<int> walked;
  const auto found = find_bad_text(*root, "", walked);
  if (bad != std::string::npos) {
    std::size_t offset = bad;
    std::string path;
    if (found) {
      // yaml-cpp counts positions in bytes of UTF-8 input: the bad byte is at or after the node's start.
      const YAML::Mark mark = found->first.Mark();
      if (mark.pos >= 0 && static_cast<std::size_t>(mark.pos) < text.size())
        if (const auto at = bad_text_offset(std::string_view(text).substr(static_cast<std::size_t>(mark.pos))))
          offset = static_cast<std::size_t>(mark.pos) + *at;
      path = found->second;
    }
    // FILE:LINE:COL of the byte itself, then the key path of the text that holds it (if any).
    throw InputError(place(offset) + (path.empty() ? "" : path + ": ") + what(offset));
  }
  if (found) {  // written as an escape ("\0", "\x01"): the text's own place and key path
    const std::string& scalar = found->first.Scalar();
    const std::size_t at = *bad_text_offset(scalar);
    throw InputError(location(name, found->first.Mark()) + ": " + (found->second.empty() ? "" : found->second + ": ") +
                     describe_byte(scalar, at) + ", byte " + std::to_string(at + 1) + " of the text (written as an escape)," +
                     why_bad(scalar, at));
  }
  return ConfigNode(*root, "", shared_name(name), root, false);
}

ConfigNode ConfigNode::load_file(const std::string& filename) {
  // Refuse devices, FIFOs and directories (/dev/zero would be read until memory runs out) and
  // oversized files before reading anything.
  std::error_code ec;
  const auto status = std::filesystem::status(filename, ec);
  if (ec || !std::filesystem::exists(status)) throw InputError(filename + ": cannot open file");
  if (!std::filesystem::is_regular_file(status)) throw InputError(filename + ": not a regular file");
  const auto size = std::filesystem::file_size(filename, ec);
  if (!ec && size > kMaxConfigBytes)
    throw InputError(filename + ": file is " + std::to_string(size) + " bytes; a config may have at most " +
                     std::to_string(kMaxConfigBytes));
  std::ifstream in(filename, std::ios::binary);
  if (!in) throw InputError(filename + ": cannot open file");
  // Read at most one byte more than allowed, in case the file grows after the size check.
  std::string text(kMaxConfigBytes + 1, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  if (in.bad()) throw InputError(filename + ": cannot read file");
  text.resize(static_cast<size_t>(in.gcount()));
  if (text.size() > kMaxConfigBytes)
    throw InputError(filename + ": file exceeds " + std::to_string(kMaxConfigBytes) + " bytes");
  ConfigNode root = load_string(text, filename);
  root.from_file_ = true;
  return root;
}

std::string ConfigNode::where() const {
  // An empty value ("key:") reports the position of the next token; its key is the better place.
  const YAML::Mark mark = node_.IsNull() && !key_mark_.is_null() ? key_mark_ : node_.Mark();
  std::string out = location(*file_, mark);
  if (!path_.empty()) out += ": " + path_;
  return out;
}

void ConfigNode::fail(const std::string& message) const { throw InputError(where() + ": " + message); }

bool ConfigNode::is_map() const { return node_.IsMap(); }
bool ConfigNode::is_sequence() const { return node_.IsSequence(); }
bool ConfigNode::is_scalar() const { return node_.IsScalar(); }

bool ConfigNode::has(const std::string& key) const { return find(key).has_value(); }

std::optional<ConfigNode> ConfigNode::find(const std::string& key) const {
  if (!node_.IsMap()) return std::nullopt;
  // Iterate instead of node_[key]: we also need the key's own mark.
  for (const auto& kv : node_) {
    if (!kv.first.IsScalar() || kv.first.Scalar() != key) continue;
    ConfigNode child(kv.second, path_.empty() ? key : path_ + "." + key, file_, root_, from_file_);
    child.key_mark_ = kv.first.Mark();
    return child;
  }
  return std::nullopt;
}

ConfigNode ConfigNode::operator[](const std::string& key) const {
  if (!node_.IsMap() && !node_.IsNull())
    fail("expected a map with key '" + key + "', got " + describe(node_));
  if (auto child = find(key)) return *child;
  // The parent map's place: an empty section reports its key instead.
  const YAML::Mark mark = node_.IsNull() && !key_mark_.is_null() ? key_mark_ : node_.Mark();
  throw InputError(location(*file_, mark) + ": missing key '" + key + "' " + in_map(path_));
}

std::vector<ConfigNode> ConfigNode::items() const {
  if (!node_.IsSequence()) fail("expected a sequence, got " + describe(node_));
  std::vector<ConfigNode> out;
  out.reserve(node_.size());
  for (size_t i = 0; i < node_.size(); ++i)
    out.push_back(ConfigNode(node_[i], path_ + "[" + std::to_string(i) + "]", file_, root_, from_file_));
  return out;
}

std::vector<std::string> ConfigNode::keys() const {
  std::vector<std::string> out;
  if (node_.IsNull()) return out;  // "section:" with nothing under it is an empty map
  if (!node_.IsMap()) fail("expected a map, got " + describe(node_));
  std::set<std::string> seen;
  for (const auto& kv : node_) {
    const std::string here = location(*file_, kv.first.Mark());
    if (!kv.first.IsScalar()) throw InputError(here + ": keys must be plain words " + in_map(path_));
    // As in check_keys: yaml-cpp would silently let one copy of a repeated key win.
    if (!seen.insert(kv.first.Scalar()).second)
      throw InputError(here + ": duplicate key '" + kv.first.Scalar() + "' " + in_map(path_));
    out.push_back(kv.first.Scalar());
  }
  return out;
}

void ConfigNode::check_keys(const std::vector<std::string>& allowed) const {
  declare(&DeclaredConfig::keys, path_, allowed);
  if (node_.IsNull()) return;
  if (!node_.IsMap()) fail("expected a map, got " + describe(node_));
  std::set<std::string> seen;
  for (const auto& kv : node_) {
    const std::string key = kv.first.IsScalar() ? kv.first.Scalar() : std::string();
    const std::string here = location(*file_, kv.first.Mark());
    if (std::find(allowed.begin(), allowed.end(), key) == allowed.end()) {
      const std::string near = nearest_word(key, allowed);
      throw InputError(
          here + ": unknown key '" + key + "' " + in_map(path_) +
          (near.empty() ? " (valid keys: " + quoted_list(allowed) + ")" : " (did you mean '" + near + "'?)"));
    }
    // yaml-cpp keeps both copies of a repeated key and lookups see only the first: refuse it.
    if (!seen.insert(key).second) throw InputError(here + ": duplicate key '" + key + "' " + in_map(path_));
  }
}

std::string ConfigNode::as_string() const {
  if (!node_.IsScalar()) fail("expected a string, got " + describe(node_));
  return node_.Scalar();
}

double ConfigNode::as_double() const {
  if (!node_.IsScalar()) fail("expected a number, got " + describe(node_));
  double value = 0;
  if (!parse_number(node_.Scalar(), value)) fail("expected a number, got '" + node_.Scalar() + "'");
  if (!std::isfinite(value)) fail("expected a finite number, got '" + node_.Scalar() + "'");
  return value;
}

int ConfigNode::as_int() const {
  if (!node_.IsScalar()) fail("expected an integer, got " + describe(node_));
  long long value = 0;
  if (!parse_number(node_.Scalar(), value)) fail("expected an integer, got '" + node_.Scalar() + "'");
  if (value < std::numeric_limits<int>::min() || value > std::numeric_limits<int>::max())
    fail("integer out of range: '" + node_.Scalar() + "'");
  return static_cast<int>(value);
}

bool ConfigNode::as_bool() const {
  // yaml-cpp's own conversion knows the YAML spellings (true/false, yes/no, on/off).
  bool value = false;
  if (!node_.IsScalar() || !YAML::convert<bool>::decode(node_, value))
    fail("expected true or false, got " + describe(node_));
  return value;
}

std::vector<double> ConfigNode::as_doubles() const {
  if (!node_.IsSequence()) fail("expected a sequence of numbers, got " + describe(node_));
  std::vector<double> out;
  for (const ConfigNode& item : items()) out.push_back(item.as_double());
  return out;
}

std::vector<int> ConfigNode::as_ints() const {
  if (!node_.IsSequence()) fail("expected a sequence of integers, got " + describe(node_));
  std::vector<int> out;
  for (const ConfigNode& item : items()) out.push_back(item.as_int());
  return out;
}

std::string ConfigNode::as_choice(const std::vector<std::string>& choices) const {
  declare(&DeclaredConfig::choices, path_, choices);
  const std::string value = as_string();
  if (std::find(choices.begin(), choices.end(), value) != choices.end()) return value;
  const std::string near = nearest_word(value, choices);
  fail("expected one of " + quoted_list(choices) + ", got '" + value + "'" +
       (near.empty() ? std::string() : " (did you mean '" + near + "'?)"));
}

std::string ConfigNode::get_string(const std::string& key, const std::string& fallback) const {
  auto child = find(key);
  return child ? child->as_string() : fallback;
}

double ConfigNode::get_double(const std::string& key, double fallback) const {
  auto child = find(key);
  return child ? child->as_double() : fallback;
}

int ConfigNode::get_int(const std::string& key, int fallback) const {
  auto child = find(key);
  return child ? child->as_int() : fallback;
}

bool ConfigNode::get_bool(const std::string& key, bool fallback) const {
  auto child = find(key);
  return child ? child->as_bool() : fallback;
}

std::string nearest_word(const std::string& word, const std::vector<std::string>& candidates) {
  // Levenshtein distance with one rolling row.
  auto distance = [](const std::string& a, const std::string& b) {
    std::vector<size_t> row(b.size() + 1);
    for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (size_t i = 1; i <= a.size(); ++i) {
      size_t diagonal = row[0];
      row[0] = i;
      for (size_t j = 1; j <= b.size(); ++j) {
        const size_t above = row[j];
        row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
        diagonal = above;
      }
    }
    return row[b.size()];
  };
  std::string best;
  size_t best_distance = std::numeric_limits<size_t>::max();
  for (const std::string& candidate : candidates) {
    const size_t d = distance(word, candidate);
    if (d < best_distance) best_distance = d, best = candidate;
  }
  // Close enough to be a typo, and not a total rewrite of a short word.
  const size_t limit = std::max<size_t>(2, word.size() / 3);
  if (best.empty() || best_distance > limit || best_distance >= std::max(word.size(), best.size())) return {};
  return best;
}

Eigen::Vector2d ConfigNode::as_point() const {
  const std::vector<double> v = as_doubles();
  if (v.size() != 2) fail("expected a point [x, y] (got " + std::to_string(v.size()) + " numbers)");
  // Larger coordinates overflow areas, Jacobians and their products to infinity far from here.
  constexpr double kMaxCoordinate = 1e100;
  if (!(std::abs(v[0]) <= kMaxCoordinate && std::abs(v[1]) <= kMaxCoordinate))
    fail("coordinates must be at most 1e100 in magnitude (got [" + format_number(v[0]) + ", " + format_number(v[1]) + "])");
  return {v[0], v[1]};
}

DeclaredConfig declared_config() {
  DeclarationRegistry& registry = declaration_registry();
  const std::lock_guard<std::mutex> lock(registry.mutex);
  return registry.declared;
}

std::string format_number(double x) {
  std::ostringstream s;
  s << x;
  return s.str();
}

}  // namespace iga
