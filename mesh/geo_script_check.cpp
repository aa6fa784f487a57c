#include "mesh/geo_script_check.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>

#include "config/config_file_path.hpp"
#include "config/config_node.hpp"
#include "config/errors.hpp"
#include "config/text_excerpt.hpp"

namespace iga {

namespace {

namespace fs = std::filesystem;

// Words refused wherever they appear (outside strings and comments): each acts outside the
// geometry (commands, files, environment, the process, interactive input).
const std::map<std::string, std::string> refused_words = {
    {"SystemCall", "runs a shell command"},
    {"System", "runs a shell command"},
    {"NonBlockingSystemCall", "runs a shell command"},
    {"NonBlockingSystem", "runs a shell command"},
    {"OnelabRun", "runs a program"},
    {"OnelabAction", "acts on the ONELAB server"},
    {"ExternalProcess", "runs a program"},
    {"Save", "writes a file"},
    {"Print", "writes a file"},
    {"CreateDir", "creates a folder"},
    {"CreateDirectory", "creates a folder"},
    {"Merge", "reads another file"},
    {"MergeWithBoundingBox", "reads another file"},
    {"ShapeFromFile", "reads another file"},
    {"Structured", "reads another file"},
    {"FileName", "names a file to read or write"},
    {"FileExists", "looks at the file system"},
    {"GetEnv", "reads the environment"},
    {"GetValue", "asks for input"},
    {"GetStringValue", "asks for input"},
    {"GetForced", "reads ONELAB parameters"},
    {"GetForcedStr", "reads ONELAB parameters"},
    {"Draw", "acts on the graphical interface"},
    {"SetChanged", "acts on the ONELAB server"},
    {"GetString", "reads ONELAB parameters"},
    {"GetNumber", "reads ONELAB parameters"},
    {"SetString", "sets ONELAB parameters"},
    {"SetNumber", "sets ONELAB parameters"},
    {"Exit", "ends the process"},
    {"Abort", "ends the script"},
    {"Sleep", "waits"},
    {"Plugin", "runs a post-processing plugin"},
    {"Homology", "runs a topology computation"},
    {"Cohomology", "runs a topology computation"},
    {"Physicals", "deletes model data"},
    {"Model", "deletes model data"},
    {"Meshes", "deletes model data"},
    {"Options", "resets options"},
    {"NewModel", "starts another model"},
    {"SendToServer", "talks to a server"},
};

// First words of the statements a 2D (or extruded) geometry needs. Assignments to variables are
// allowed besides; everything else is refused.
// clang-format off
const std::set<std::string> allowed_heads = {
    "Point", "Line", "Curve", "Circle", "Ellipse", "Spline", "BSpline", "Bezier", "Nurbs", "Wire", "Surface",
    "Plane", "Ruled", "Volume", "Sphere", "Box", "Cylinder", "Torus", "Cone", "Wedge", "Rectangle", "Disk",
    "Physical", "Transfinite", "Recombine", "Smoother", "Periodic", "Compound", "Reverse", "MeshAlgorithm",
    "MeshSize", "Characteristic", "Field", "Background", "Extrude", "Translate", "Rotate", "Symmetry", "Dilate",
    "Affine", "Duplicata", "Delete", "Recursive", "Coherence", "Fillet", "Chamfer", "ThruSections",
    "BooleanUnion", "BooleanIntersection", "BooleanDifference", "BooleanFragments", "SetFactory", "Hide", "Show",
    "Color", "Printf", "Error", "Warning", "Mesh", "Geometry", "Include", "Call", "DefineConstant",
    "SyncModel", "Boundary", "CombinedBoundary", "ThickSolid", "Struct"};
// clang-format on

// Field types that only compute sizes (Structured reads a file, ExternalProcess runs a program,
// PostView needs a view, which only a file could bring).
// clang-format off
const std::set<std::string> allowed_fields = {
    "Attractor", "AttractorAnisoCurve", "Ball", "BoundaryLayer", "Box", "Constant", "Curvature", "Cylinder", "Extend",
    "Distance", "Frustum", "Gradient", "IntersectAniso", "Laplacian", "LonLat", "MathEval",
    "MathEvalAniso", "Max", "MaxEigenHessian", "Mean", "Min", "MinAniso", "Octree", "Param",
    "Restrict", "Threshold"};
// clang-format on

// The option categories of Gmsh; only Mesh and Geometry options (numbers and colours, nothing that
// names a file) may be set.
const std::set<std::string> option_categories = {"General",        "Geometry", "Mesh", "Solver",
                                                 "PostProcessing", "View",     "Print"};

// Words that continue a statement after a closing brace (`Point{5} In Surface{1};`,
// `Extrude { Surface{1}; } Using Wire {2}`).
// clang-format off
const std::set<std::string> continuations = {"In",   "Using", "Knots",         "Order",         "Alternate",
                                             "Left", "Right", "AlternateLeft", "AlternateRight"};
// clang-format on

struct Token {
  enum Kind { word, number, text, punct } kind;
  std::string s;
  int line;
};

struct Script {
  fs::path file;
  std::vector<Token> tokens;

  [[noreturn]] void fail(int line, const std::string& message) const {
    throw InputError(file.string() + ":" + std::to_string(line) + ": " + message);
  }
};

Script tokenize(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in || fs::is_directory(file)) throw InputError(file.string() + ": cannot read the mesh script");
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string t = buffer.str();
  Script script{file, {}};
  int line = 1;
  for (std::size_t i = 0; i < t.size();) {
    const char c = t[i];
    if (c == '\n') {
      ++line;
      ++i;
    } else if (std::isspace(static_cast<unsigned char>(c))) {
      ++i;
    } else if (t.compare(i, 2, "//") == 0) {
      while (i < t.size() && t[i] != '\n') ++i;
    } else if (t.compare(i, 2, "/*") == 0) {
      const int start = line;
      std::size_t j = i + 2;
      for (; j + 1 < t.size() && t.compare(j, 2, "*/") != 0; ++j) line += t[j] == '\n';
      if (j + 1 >= t.size()) script.fail(start, "unterminated /* comment");
      i = j + 2;
    } else if (c == '"') {
      const int start = line;
      std::string s;
      std::size_t j = i + 1;
      for (; j < t.size() && t[j] != '"'; ++j) {
        if (t[j] == '\\' && j + 1 < t.size()) s += t[j++];
        line += t[j] == '\n';
        s += t[j];
      }
      if (j >= t.size()) script.fail(start, "unterminated string");
      script.tokens.push_back({Token::text, s, start});
      i = j + 1;
    } else if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
      std::size_t j = i;
      while (j < t.size() && (std::isalnum(static_cast<unsigned char>(t[j])) || t[j] == '_')) ++j;
      script.tokens.push_back({Token::word, t.substr(i, j - i), line});
      i = j;
    } else if (std::isdigit(static_cast<unsigned char>(c)) ||
               (c == '.' && i + 1 < t.size() && std::isdigit(static_cast<unsigned char>(t[i + 1])))) {
      std::size_t j = i;
      while (j < t.size() && (std::isalnum(static_cast<unsigned char>(t[j])) || t[j] == '.' ||
                              ((t[j] == '+' || t[j] == '-') && (t[j - 1] == 'e' || t[j - 1] == 'E'))))
        ++j;
      script.tokens.push_back({Token::number, t.substr(i, j - i), line});
      i = j;
    } else {
      static const char* const pairs[] = {"+=", "-=", "*=", "/=", "++", "--", "==", "!=", "<=", ">=", "&&", "||", ">>"};
      std::string op(1, c);
      for (const char* p : pairs)
        if (t.compare(i, 2, p) == 0) op = p;
      script.tokens.push_back({Token::punct, op, line});
      i += op.size();
    }
  }
  return script;
}

bool is(const Token& t, const char* s) { return t.s == s && t.kind != Token::text; }

/// Index of the token closing the bracket opened at `open` (or tokens.size()).
std::size_t matching(const std::vector<Token>& tokens, std::size_t open) {
  int depth = 0;
  for (std::size_t k = open; k < tokens.size(); ++k) {
    if (tokens[k].kind != Token::punct) continue;
    const std::string& s = tokens[k].s;
    depth += (s == "(" || s == "[" || s == "{") - (s == ")" || s == "]" || s == "}");
    if (depth == 0) return k;
  }
  return tokens.size();
}

/// Numbers, variables known to hold numbers, + - * / ^ and parentheses; nullopt otherwise.
class ConstantExpression {
 public:
  ConstantExpression(const std::vector<Token>& tokens, std::size_t begin, std::size_t end,
                     const std::map<std::string, double>& values)
      : t_(tokens), k_(begin), end_(end), values_(values) {}

  std::optional<double> value() {
    const auto v = sum();
    return k_ == end_ ? v : std::nullopt;
  }

 private:
  std::optional<double> sum() {
    auto v = product();
    while (v && k_ < end_ && (is(t_[k_], "+") || is(t_[k_], "-"))) {
      const bool plus = is(t_[k_++], "+");
      const auto w = product();
      if (!w) return std::nullopt;
      v = plus ? *v + *w : *v - *w;
    }
    return v;
  }
  std::optional<double> product() {
    auto v = power();
    while (v && k_ < end_ && (is(t_[k_], "*") || is(t_[k_], "/"))) {
      const bool times = is(t_[k_++], "*");
      const auto w = power();
      if (!w) return std::nullopt;
      v = times ? *v * *w : *v / *w;
    }
    return v;
  }
  std::optional<double> power() {
    auto v = unary();
    if (v && k_ < end_ && is(t_[k_], "^")) {
      ++k_;
      const auto w = power();
      if (!w) return std::nullopt;
      v = std::pow(*v, *w);
    }
    return v;
  }
  std::optional<double> unary() {
    if (k_ >= end_) return std::nullopt;
    const Token& t = t_[k_];
    if (is(t, "-") || is(t, "+")) {
      ++k_;
      const auto v = unary();
      return v && is(t, "-") ? std::optional<double>(-*v) : v;
    }
    if (is(t, "(")) {
      ++k_;
      const auto v = sum();
      if (!v || k_ >= end_ || !is(t_[k_], ")")) return std::nullopt;
      ++k_;
      return v;
    }
    if (t.kind == Token::number) {
      ++k_;
      char* stop = nullptr;
      const double x = std::strtod(t.s.c_str(), &stop);
      return *stop == '\0' ? std::optional<double>(x) : std::nullopt;
    }
    if (t.kind == Token::word) {
      const auto it = values_.find(t.s);
      if (it == values_.end()) return std::nullopt;
      ++k_;
      return it->second;
    }
    return std::nullopt;
  }

  const std::vector<Token>& t_;
  std::size_t k_, end_;
  const std::map<std::string, double>& values_;
};

class ScriptChecker {
 public:
  ScriptChecker(const std::vector<fs::path>& roots, const MeshLimits& limits) : limits_(limits) {
    for (const auto& r : roots) roots_.push_back(fs::weakly_canonical(r));
  }

  /// The top-level script and "<file>.opt" (Gmsh also runs it when it opens <file>: a script in
  /// the same language) are read only inside the roots, like Includes: a link beside the mesh
  /// that points out of its folders is refused before it is read (the Gmsh worker could not read
  /// it either). A name that does not exist is left to tokenize ("cannot read").
  void check_confined(const fs::path& file, std::vector<fs::path>& stack) {
    std::error_code ec;
    if (fs::exists(fs::symlink_status(file, ec))) {
      const fs::path real = fs::weakly_canonical(file, ec);
      if (ec || !fs::exists(real, ec)) throw InputError(file.string() + ": is a link to a file that does not exist");
      if (!inside_roots(real))
        throw InputError(file.string() + ": is outside the folder of the config and the mesh file (links resolved)");
    }
    check(file, stack);
  }

  /// check_confined on `file` and on "<file>.opt" when there is one.
  void check_with_options(const fs::path& file, std::vector<fs::path>& stack) {
    check_confined(file, stack);
    const fs::path options = file.string() + ".opt";
    if (std::error_code ec; fs::exists(fs::symlink_status(options, ec))) check_confined(options, stack);
  }

  void check(const fs::path& file, std::vector<fs::path>& stack) {
    const Script script = tokenize(file);
    checked_.push_back(file);
    const auto& t = script.tokens;
    for (const Token& token : t)
      if (token.kind == Token::word)
        if (const auto it = refused_words.find(token.s); it != refused_words.end())
          script.fail(token.line, quoted_excerpt(token.s) + " is not allowed in a mesh script (it " + it->second +
                                      "); only geometry and mesh statements are");
    for (std::size_t i = 0; i < t.size();) {
      const Token& head = t[i];
      if (is(head, ";")) {
        ++i;
        continue;
      }
      if (head.kind != Token::word) script.fail(head.line, "a statement cannot start with " + quoted_excerpt(head.s));
      if (head.s == "For") {
        i = for_header(script, i);
        continue;
      }
      if (head.s == "EndFor" || head.s == "Else" || head.s == "EndIf" || head.s == "Return") {
        ++i;
        continue;
      }
      if (head.s == "If" || head.s == "ElseIf") {
        if (i + 1 >= t.size() || !is(t[i + 1], "(")) script.fail(head.line, "expected '(' after " + head.s);
        const std::size_t close = matching(t, i + 1);
        check_ranges(script, i + 1, close);
        i = close + 1;
        continue;
      }
      if (head.s == "Macro" || head.s == "Function") {
        i += 2;
        continue;
      }
      // A statement ends at ';' or, like `Delete { Point{1}; }`, at a closing brace followed by a
      // word that starts the next statement.
      std::size_t end = i;
      bool after_brace = false;
      for (int depth = 0; end < t.size(); ++end) {
        if (t[end].kind != Token::punct) continue;
        const std::string& s = t[end].s;
        depth += (s == "(" || s == "[" || s == "{") - (s == ")" || s == "]" || s == "}");
        if (s == ";" && depth <= 0) break;
        if (s == "}" && depth == 0 &&
            (end + 1 == t.size() || (t[end + 1].kind == Token::word && !continuations.count(t[end + 1].s)))) {
          after_brace = true;
          break;
        }
      }
      if (end >= t.size()) script.fail(head.line, "the statement " + quoted_excerpt(head.s + " ...") + " does not end with ';'");
      if (after_brace) ++end;  // the brace belongs to the statement
      statement(script, i, end, stack);
      i = after_brace ? end : end + 1;
    }
  }

 private:
  [[noreturn]] void refuse(const Script& s, const Token& head, const std::string& why) const {
    s.fail(head.line, "the statement " + quoted_excerpt(head.s + " ...") + " is not allowed in a mesh script: " + why);
  }

  void statement(const Script& script, std::size_t i, std::size_t end, std::vector<fs::path>& stack) {
    const auto& t = script.tokens;
    const Token& head = t[i];
    check_ranges(script, i, end);
    const bool dotted = i + 1 < end && is(t[i + 1], ".");
    if (option_categories.count(head.s) && dotted) {
      if (head.s != "Mesh" && head.s != "Geometry")
        refuse(script, head, "only Mesh.* and Geometry.* options may be set");
      for (std::size_t k = i; k < end; ++k)
        if (t[k].kind == Token::text) refuse(script, head, "options may only be set to numbers");
      return;
    }
    if (allowed_heads.count(head.s)) {
      if (head.s == "Mesh" || head.s == "Geometry")
        refuse(script, head, "meshing inside the script (the mesh is made after the script ran)");
      if (head.s == "Include") return include(script, i, end, stack);
      if (head.s == "Printf")
        for (std::size_t k = i; k < end; ++k)
          if (is(t[k], ">") || is(t[k], ">>")) refuse(script, head, "Printf may not write to a file");
      if (head.s == "Delete" && !(i + 1 < end && is(t[i + 1], "{")))
        refuse(script, head, "only 'Delete { entities }' is allowed");
      if (head.s == "Field" && i + 1 < end && is(t[i + 1], "[")) {
        const std::size_t close = matching(t, i + 1);
        if (close + 2 < end && is(t[close + 1], "=") && t[close + 2].kind == Token::word &&
            !allowed_fields.count(t[close + 2].s))
          refuse(script, head, "the Field type " + quoted_excerpt(t[close + 2].s) + " is not allowed");
      }
      if (head.s == "Point") point_size(script, i, end);
      if (head.s == "MeshSize" || (head.s == "Characteristic" && i + 1 < end && is(t[i + 1], "Length")))
        size_assignment(script, i, end);
      track_assignment(script, i, end);
      return;
    }
    // Otherwise it must be an assignment to a variable: name[...] = ..., name += ..., name++ ...
    for (std::size_t k = i + 1; k < end; ++k)
      if (t[k].kind == Token::punct && (t[k].s == "=" || t[k].s == "+=" || t[k].s == "-=" || t[k].s == "*=" ||
                                        t[k].s == "/=" || t[k].s == "++" || t[k].s == "--")) {
        track_assignment(script, i, end);
        return;
      }
    refuse(script, head, "it is neither an assignment nor a geometry or mesh statement");
  }

  /// The value of `[begin, end)` as a mesh size: +inf when it cannot be evaluated here (a loop
  /// variable, a function call) or is not a positive number, i.e. "no bound known".
  double size_value(const std::vector<Token>& t, std::size_t begin, std::size_t end) const {
    const auto v = ConstantExpression(t, begin, end, values_).value();
    return v && *v > 0.0 && std::isfinite(*v) ? *v : std::numeric_limits<double>::infinity();
  }

  /// Positions of the top-level commas in tokens (open, close).
  static std::vector<std::size_t> top_level_commas(const std::vector<Token>& t, std::size_t open, std::size_t close) {
    std::vector<std::size_t> commas;
    int depth = 0;
    for (std::size_t k = open + 1; k < close; ++k) {
      if (t[k].kind != Token::punct) continue;
      if (t[k].s == "(" || t[k].s == "[" || t[k].s == "{") ++depth;
      if (t[k].s == ")" || t[k].s == "]" || t[k].s == "}") --depth;
      if (depth == 0 && t[k].s == ",") commas.push_back(k);
    }
    return commas;
  }

  /// The point ids of a list `{1, 2, a:b}` (tokens open..close), or nullopt when an item cannot be
  /// evaluated here or a range is long (it is then counted as unknown points).
  std::optional<std::vector<double>> id_list(const std::vector<Token>& t, std::size_t open, std::size_t close) const {
    std::vector<std::size_t> cuts = top_level_commas(t, open, close);
    cuts.insert(cuts.begin(), open);
    cuts.push_back(close);
    std::vector<double> ids;
    for (std::size_t p = 0; p + 1 < cuts.size(); ++p) {
      std::size_t colon = cuts[p + 1];
      for (std::size_t k = cuts[p] + 1; k < cuts[p + 1]; ++k)
        if (is(t[k], ":")) colon = std::min(colon, k);
      const auto first = ConstantExpression(t, cuts[p] + 1, colon, values_).value();
      if (!first) return std::nullopt;
      if (colon == cuts[p + 1]) {
        ids.push_back(*first);
        continue;
      }
      const auto last = ConstantExpression(t, colon + 1, cuts[p + 1], values_).value();
      if (!last || !(*last - *first >= 0.0 && *last - *first < 1e4)) return std::nullopt;
      for (double id = *first; id <= *last; ++id) ids.push_back(id);
    }
    return ids;
  }

  /// `Point(n) = {x, y, z, lc};`: point n gets size lc (+inf without lc: no size of its own,
  /// Gmsh takes the model's there). A point whose id cannot be evaluated counts in `untracked_size`.
  void point_size(const Script& script, std::size_t i, std::size_t end) {
    const auto& t = script.tokens;
    if (i + 1 >= end || !is(t[i + 1], "(")) return;
    const std::size_t id_close = matching(t, i + 1);
    if (id_close + 2 >= end || !is(t[id_close + 1], "=") || !is(t[id_close + 2], "{"))
      return;  // `Point{5} In Surface{1};` gives no size
    const std::size_t open = id_close + 2;
    const std::size_t close = std::min(matching(t, open), end);
    const std::vector<std::size_t> commas = top_level_commas(t, open, close);
    const double lc = commas.size() == 3 ? size_value(t, commas[2] + 1, close) : std::numeric_limits<double>::infinity();
    if (const auto id = ConstantExpression(t, i + 2, id_close, values_).value())
      point_sizes_[*id] = lc;
    else
      untracked_size_ = std::max(untracked_size_, lc);
  }

  /// `MeshSize {points} = lc;` and `Characteristic Length {points} = lc;` replace the sizes of
  /// the listed points (of every point it may name when the list cannot be evaluated here).
  void size_assignment(const Script& script, std::size_t i, std::size_t end) {
    const auto& t = script.tokens;
    std::size_t open = i + 1;
    while (open < end && !is(t[open], "{")) ++open;
    if (open >= end) return;
    const std::size_t close = matching(t, open);
    if (close + 1 >= end || !is(t[close + 1], "=")) return;
    const double lc = size_value(t, close + 2, end);
    const auto ids = id_list(t, open, close);
    if (!ids) {
      untracked_size_ = std::max(untracked_size_, lc);
      return;
    }
    for (double id : *ids) {
      const auto it = point_sizes_.find(id);
      if (it != point_sizes_.end())
        it->second = lc;
      else
        untracked_size_ = std::max(untracked_size_, lc);  // a point made by an extrusion or a copy
    }
  }

  /// Remembers `name = <constant>;` for loop bounds; forgets a name assigned anything else.
  void track_assignment(const Script& script, std::size_t i, std::size_t end) {
    const auto& t = script.tokens;
    if (t[i].kind != Token::word || allowed_heads.count(t[i].s)) return;
    if (i + 1 < end && is(t[i + 1], "=")) {
      if (const auto v = ConstantExpression(t, i + 2, end, values_).value()) {
        values_[t[i].s] = *v;
        return;
      }
    }
    values_.erase(t[i].s);
  }

  /// Whether `real` (links resolved) lies below one of the folders Includes may read from.
  bool inside_roots(const fs::path& real) const {
    return std::any_of(roots_.begin(), roots_.end(),
                       [&](const fs::path& root) { return path_strictly_within(real, root); });
  }

  void include(const Script& script, std::size_t i, std::size_t end, std::vector<fs::path>& stack) {
    const auto& t = script.tokens;
    const Token& head = t[i];
    if (end != i + 2 || t[i + 1].kind != Token::text) refuse(script, head, "Include needs a literal \"path\"");
    fs::path target = t[i + 1].s;
    if (target.is_relative()) target = script.file.parent_path() / target;
    std::error_code ec;
    const fs::path real = fs::weakly_canonical(target, ec);
    if (ec || !inside_roots(real)) refuse(script, head, quoted_excerpt(t[i + 1].s) + " is outside the folder of the config and the mesh file");
    if (!fs::is_regular_file(real, ec)) refuse(script, head, quoted_excerpt(t[i + 1].s) + " is not a readable file");
    for (const auto& open : stack)
      if (open == real) refuse(script, head, quoted_excerpt(t[i + 1].s) + " includes itself (a cycle of Includes)");
    if (stack.size() > 16) refuse(script, head, "Includes nest more than 16 deep");
    stack.push_back(real);
    check(real, stack);
    stack.pop_back();
  }

  /// `For (a:b:s)` or `For i In {a:b:s}`: the header's range is checked; returns the index after it.
  std::size_t for_header(const Script& script, std::size_t i) {
    const auto& t = script.tokens;
    std::size_t open = i + 1;
    if (open < t.size() && t[open].kind == Token::word) {
      if (open + 1 >= t.size() || !is(t[open + 1], "In")) script.fail(t[i].line, "expected 'For name In {a:b}'");
      values_.erase(t[open].s);
      open += 2;
    }
    if (open >= t.size() || !(is(t[open], "(") || is(t[open], "{")))
      script.fail(t[i].line, "expected a range after For");
    const std::size_t close = matching(t, open);
    if (close >= t.size()) script.fail(t[i].line, "unterminated For range");
    check_ranges(script, open, close + 1);
    return close + 1;
  }

  /// Every {a:b[:s]} or (a:b[:s]) list in tokens [begin, end) whose bounds can be evaluated.
  void check_ranges(const Script& script, std::size_t begin, std::size_t end) const {
    const auto& t = script.tokens;
    for (std::size_t k = begin; k < end; ++k) {
      if (!(is(t[k], "{") || is(t[k], "("))) continue;
      const std::size_t close = std::min(matching(t, k), end);
      std::vector<std::size_t> colons;
      int depth = 0;
      for (std::size_t j = k + 1; j < close; ++j) {
        if (t[j].kind != Token::punct) continue;
        if (t[j].s == "(" || t[j].s == "[" || t[j].s == "{") ++depth;
        if (t[j].s == ")" || t[j].s == "]" || t[j].s == "}") --depth;
        if (depth == 0 && (t[j].s == ":" || t[j].s == ",")) colons.push_back(t[j].s == ":" ? j : 0);
      }
      // Only a list that is a single range a:b or a:b:s (no commas) is evaluated here.
      if (colons.empty() || colons.size() > 2 || std::count(colons.begin(), colons.end(), 0)) continue;
      std::vector<std::size_t> cuts = {k};
      cuts.insert(cuts.end(), colons.begin(), colons.end());
      cuts.push_back(close);
      std::vector<double> v;
      for (std::size_t p = 0; p + 1 < cuts.size(); ++p)
        if (const auto x = ConstantExpression(t, cuts[p] + 1, cuts[p + 1], values_).value()) v.push_back(*x);
      if (v.size() != cuts.size() - 1) continue;
      const double step = v.size() == 3 ? v[2] : 1.0;
      if (!std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(step))
        script.fail(t[k].line, "the range " + format_number(v[0]) + ":" + format_number(v[1]) + " is not finite");
      if (step == 0.0) script.fail(t[k].line, "a range with step 0 never ends");
      const double count = std::floor((v[1] - v[0]) / step) + 1.0;
      if (count > limits_.max_loop_iterations)
        script.fail(t[k].line, "the range " + format_number(v[0]) + ":" + format_number(v[1]) +
                                   (v.size() == 3 ? ":" + format_number(step) : "") + " has " + format_number(count) +
                                   " values, more than the limit of " + format_number(limits_.max_loop_iterations));
    }
  }

  std::vector<fs::path> roots_;
  MeshLimits limits_;

 public:
  std::vector<fs::path> checked_;

  /// The largest size a point has at the end of the script (0 without points; +inf when one is
  /// unknown).
  double largest_point_size() const {
    double largest = untracked_size_;
    for (const auto& [id, lc] : point_sizes_) largest = std::max(largest, lc);
    return largest;
  }

 private:
  std::map<double, double> point_sizes_;  ///< point id -> its size (+inf: none or unknown)
  double untracked_size_ = 0.0;           ///< largest size of points whose id is not known here

  std::map<std::string, double> values_;
};

}  // namespace

std::vector<fs::path> check_geo_script(const fs::path& file, const std::vector<fs::path>& include_roots,
                                       const MeshLimits& limits) {
  ScriptChecker checker(include_roots, limits);
  std::vector<fs::path> stack = {fs::weakly_canonical(file)};
  checker.check_with_options(file, stack);
  return checker.checked_;
}

double geo_script_largest_point_size(const fs::path& file, const std::vector<fs::path>& include_roots,
                                     const MeshLimits& limits) {
  ScriptChecker checker(include_roots, limits);
  std::vector<fs::path> stack = {fs::weakly_canonical(file)};
  try {
    checker.check_with_options(file, stack);
  } catch (const InputError&) {
    // Not this function's verdict (check_geo_script gives it; the Gmsh worker's own tests run
    // refused scripts on purpose): no bound is known.
    return std::numeric_limits<double>::infinity();
  }
  const double largest = checker.largest_point_size();
  return largest > 0.0 ? largest : std::numeric_limits<double>::infinity();
}

}  // namespace iga
