#pragma once
/// @file
/// ConfigNode: a YAML node that knows where it came from (file, line, column, key path), so every
/// error about the config names its place. Unknown keys are errors that suggest the nearest valid key.

#include <yaml-cpp/yaml.h>

#include <Eigen/Core>

#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "config/errors.hpp"

namespace iga {

class ConfigNode {
 public:
  /// Largest config file load_file reads (a config is a few hundred bytes; this is generous).
  static constexpr size_t kMaxConfigBytes = 1 << 20;
  /// Parse a YAML file. Throws InputError "FILE:LINE:COL: ..." on a syntax error, a missing file,
  /// something that is not a regular file (a device, a FIFO, a directory) or a file over
  /// kMaxConfigBytes.
  static ConfigNode load_file(const std::string& filename);
  /// Parse YAML text (for tests and embedding); `name` stands for the file name in messages.
  static ConfigNode load_string(const std::string& text, const std::string& name = "<string>");

  /// Dotted key path of this node, e.g. "space.degree" (empty for the root).
  const std::string& path() const { return path_; }
  /// The whole config this node belongs to (its root map), e.g. for a builder handed only the
  /// `domain:` section that must also honour the config's `limits:`.
  ConfigNode root() const;
  /// "FILE:LINE:COL: path" for messages (fail() appends ": message").
  std::string where() const;
  /// Throw InputError "where(): message".
  [[noreturn]] void fail(const std::string& message) const;
  /// Runs `build`; an InputError it throws (a mesh file's message, say) is reported at this node
  /// instead, as "FILE:LINE:COL: key: message".
  template <class Build>
  auto guard(Build&& build) const {
    try {
      return build();
    } catch (const InputError& e) {
      fail(e.what());
    }
  }

  bool is_map() const;
  bool is_sequence() const;
  bool is_scalar() const;
  bool has(const std::string& key) const;
  /// Child of a map; throws InputError naming the missing key.
  ConfigNode operator[](const std::string& key) const;
  /// Child of a map if present.
  std::optional<ConfigNode> find(const std::string& key) const;
  /// Elements of a sequence.
  std::vector<ConfigNode> items() const;
  /// Keys of a map, in file order.
  std::vector<std::string> keys() const;
  /// Every key of this map must be one of `allowed`; otherwise InputError
  /// "FILE:LINE:COL: unknown key 'degre' in 'space' (did you mean 'degree'?)".
  void check_keys(const std::vector<std::string>& allowed) const;

  /// Typed values; a wrong type is an InputError naming the place and the expected type.
  std::string as_string() const;
  double as_double() const;
  int as_int() const;
  bool as_bool() const;
  std::vector<double> as_doubles() const;
  std::vector<int> as_ints() const;
  /// A point [x, y]; anything else is an InputError naming the place.
  Eigen::Vector2d as_point() const;
  /// The scalar must be one of `choices`; otherwise InputError listing them (with a suggestion).
  std::string as_choice(const std::vector<std::string>& choices) const;

  /// Value of an optional key, or `fallback` when absent.
  std::string get_string(const std::string& key, const std::string& fallback) const;
  double get_double(const std::string& key, double fallback) const;
  int get_int(const std::string& key, int fallback) const;
  bool get_bool(const std::string& key, bool fallback) const;

  const YAML::Node& yaml() const { return node_; }
  const std::string& file() const { return *file_; }
  /// Whether the config was read by load_file: file() is then a real file, whose folder is the
  /// only place the files the config names may be read from (see config/config_file_path.hpp).
  bool from_file() const { return from_file_; }

 private:
  ConfigNode(YAML::Node node, std::string path, std::shared_ptr<const std::string> file,
             std::shared_ptr<const YAML::Node> root, bool from_file);
  YAML::Node node_;
  std::string path_;
  std::shared_ptr<const std::string> file_;
  std::shared_ptr<const YAML::Node> root_;
  bool from_file_ = false;
  YAML::Mark key_mark_ = YAML::Mark::null_mark();  ///< of the key; an empty value has no place of its own
};

/// What the parser has declared so far in this process (the configuration-reference test compares
/// it with docs/configuration.md). Paths are dotted with list indices written "[]", e.g.
/// "space.refine_near[].curve"; the root map's path is empty.
struct DeclaredConfig {
  std::map<std::string, std::set<std::string>> keys;     ///< map path -> keys check_keys allowed there
  std::map<std::string, std::set<std::string>> choices;  ///< value path -> values as_choice offered there
};
/// A copy of everything check_keys and as_choice have declared in this process (thread-safe).
DeclaredConfig declared_config();

/// A number as messages show it: shortest natural form ("0.5", "3", "1e-06").
std::string format_number(double x);

/// Levenshtein-nearest of `candidates` to `word`, or empty when none is close (for suggestions).
std::string nearest_word(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace iga
