#include "mesh/msh_structure_check.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <unordered_set>
#include <vector>

#include "config/config_node.hpp"
#include "config/errors.hpp"
#include "config/utf8.hpp"
#include "config/text_excerpt.hpp"

namespace iga {

namespace {

constexpr long long max_tag = 2147483647;  // Gmsh's MSH 2 reader stores tags as int

/// Nodes per element of each type Gmsh defines (MSH format documentation), and its dimension.
struct ElementKind {
  int nodes, dim;
};
const std::map<long long, ElementKind> element_kinds = {
    {1, {2, 1}},   {2, {3, 2}},   {3, {4, 2}},   {4, {4, 3}},   {5, {8, 3}},   {6, {6, 3}},   {7, {5, 3}},
    {8, {3, 1}},   {9, {6, 2}},   {10, {9, 2}},  {11, {10, 3}}, {12, {27, 3}}, {13, {18, 3}}, {14, {14, 3}},
    {15, {1, 0}},  {16, {8, 2}},  {17, {20, 3}}, {18, {15, 3}}, {19, {13, 3}}, {20, {9, 2}},  {21, {10, 2}},
    {22, {12, 2}}, {23, {15, 2}}, {24, {15, 2}}, {25, {21, 2}}, {26, {4, 1}},  {27, {5, 1}},  {28, {6, 1}},
    {29, {20, 3}}, {30, {35, 3}}, {31, {56, 3}}, {92, {64, 3}}, {93, {125, 3}}};

class MshChecker {
 public:
  MshChecker(const std::string& path, const MeshLimits& limits) : path_(path), in_(path), limits_(limits) {
    if (!in_) throw InputError(path + ": cannot read the mesh file");
  }

  void run() {
    std::vector<std::string> t;
    if (!next(t) || t.size() != 1 || t[0] != "$MeshFormat") fail("expected '$MeshFormat' as the first line");
    if (!next(t) || t.size() != 3) fail("expected 'version file-type data-size' after $MeshFormat");
    version_ = t[0];
    if (t[1] == "1") fail("binary .msh files are not supported; save the mesh as ASCII (Mesh.Binary = 0)");
    if (t[1] != "0") fail("file-type must be 0 (ASCII), got " + quoted_excerpt(t[1]));
    if (version_ == "4.1")
      v4_ = true;
    else if (version_ != "2.2" && version_ != "2.1" && version_ != "2.0" && version_ != "2")
      fail("MSH version " + version_ + " is not supported (2.2 or 4.1; Mesh.MshFileVersion)");
    expect_end("MeshFormat");
    while (next(t)) {
      if (t[0].empty() || t[0][0] != '$' || t.size() != 1)
        fail("expected a section header '$Name', got " + quoted_excerpt(t[0]));
      const std::string name = t[0].substr(1);
      if (name.rfind("End", 0) == 0) fail(quoted_excerpt(t[0]) + " closes no open section");
      if (!seen_.insert(name).second) fail("a second $" + name + " section");
      if (name == "Nodes")
        v4_ ? nodes_v4() : nodes_v2();
      else if (name == "Elements")
        v4_ ? elements_v4() : elements_v2();
      else if (name == "Entities" && v4_)
        entities();
      else if (name == "PhysicalNames")
        physical_names();
      else if (name == "PartitionedEntities")
        fail("partitioned meshes are not supported");
      else
        skip(name);
    }
    if (!seen_.count("Nodes")) fail_at_end("the file has no $Nodes section");
    if (!seen_.count("Elements")) fail_at_end("the file has no $Elements section");
    for (const auto& [tag, line] : later_nodes_)
      if (!nodes_.count(tag))
        throw InputError(path_ + ":" + std::to_string(line) + ": an element uses node " + std::to_string(tag) +
                         ", which the $Nodes section does not define");
    if (seen_.count("Entities"))
      for (const auto& [entity, line] : used_entities_)
        if (!entities_.count(entity))
          throw InputError(path_ + ":" + std::to_string(line) + ": the block refers to entity (dim " +
                           std::to_string(entity.first) + ", tag " + std::to_string(entity.second) +
                           "), which the $Entities section does not define");
    if (static_cast<double>(surface_elements_) > limits_.max_elements)
      fail_at_end("the mesh has " + std::to_string(surface_elements_) + " 2D elements, more than the limit of " +
                  format_number(limits_.max_elements) + " (limits.max_elements in the config)");
  }

 private:
  [[noreturn]] void fail(const std::string& message) const {
    throw InputError(path_ + ":" + std::to_string(line_) + ": " + message);
  }
  [[noreturn]] void fail_at(int line, const std::string& message) const {
    throw InputError(path_ + ":" + std::to_string(line) + ": " + message);
  }
  [[noreturn]] void fail_at_end(const std::string& message) const { throw InputError(path_ + ": " + message); }

  /// The next non-empty line split at white space; false at the end of the file.
  bool next(std::vector<std::string>& tokens) {
    for (std::string text; std::getline(in_, text);) {
      ++line_;
      tokens.clear();
      std::istringstream s(text);
      for (std::string w; s >> w;) tokens.push_back(w);
      if (!tokens.empty()) return true;
    }
    return false;
  }
  void need(std::vector<std::string>& t, const std::string& what) {
    if (!next(t)) fail_at_end("the file ends inside " + what);
    if (t[0][0] == '$') fail("expected " + what + ", got " + quoted_excerpt(t[0]));
  }
  void expect_end(const std::string& name) {
    std::vector<std::string> t;
    if (!next(t)) fail_at_end("$" + name + " is not closed by $End" + name);
    if (t.size() != 1 || t[0] != "$End" + name)
      fail("expected '$End" + name + "' (the counts above do not match the data), got '" + t[0] + "'");
  }
  void skip(const std::string& name) {
    std::vector<std::string> t;
    while (next(t))
      if (t[0] == "$End" + name) return;
    fail_at_end("$" + name + " is not closed by $End" + name);
  }

  long long integer(const std::string& token, const char* what) const {
    long long i = 0;
    const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), i);
    if (error != std::errc() || end != token.data() + token.size())
      fail(std::string("expected ") + what + " (an integer), got " + quoted_excerpt(token));
    return i;
  }
  long long count(const std::string& token, const char* what, double limit) const {
    const long long n = integer(token, what);
    if (n < 0) fail(std::string(what) + " is negative");
    if (static_cast<double>(n) > limit)
      fail(std::string(what) + " " + token + " is more than the limit of " + format_number(limit));
    return n;
  }
  long long tag(const std::string& token, const char* what) const {
    const long long i = integer(token, what);
    if (i < 1 || i > max_tag) fail(std::string(what) + " " + token + " is not in [1, 2147483647]");
    return i;
  }
  double coordinate(const std::string& token) const {
    double x = 0.0;
    const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), x);
    if (error != std::errc() || end != token.data() + token.size()) fail("expected a coordinate, got " + quoted_excerpt(token));
    if (!std::isfinite(x)) fail("coordinate " + quoted_excerpt(token) + " is not finite");
    return x;
  }
  /// Header counts (nodes, all elements including lines and points) are refused beyond this.
  double limit() const { return 4.0 * limits_.max_elements; }

  void add_node(long long t) {
    if (!nodes_.insert(t).second) fail("node " + std::to_string(t) + " is defined twice");
  }

  void nodes_v2() {
    std::vector<std::string> t;
    need(t, "the node count");
    if (t.size() != 1) fail("expected the node count alone on its line");
    const long long n = count(t[0], "node count", limit());
    for (long long k = 0; k < n; ++k) {
      need(t, "node " + std::to_string(k + 1) + " of " + std::to_string(n));
      if (t.size() != 4) fail("a node needs 'tag x y z'");
      add_node(tag(t[0], "node tag"));
      for (int c = 1; c < 4; ++c) coordinate(t[c]);
    }
    expect_end("Nodes");
  }

  void nodes_v4() {
    std::vector<std::string> t;
    need(t, "the nodes header");
    if (t.size() != 4) fail("expected 'numEntityBlocks numNodes minNodeTag maxNodeTag'");
    const long long blocks = count(t[0], "block count", limit());
    const long long n = count(t[1], "node count", limit());
    const long long lo = integer(t[2], "minNodeTag"), hi = integer(t[3], "maxNodeTag");
    const int header = line_;
    long long total = 0, seen_lo = 0, seen_hi = 0;
    for (long long b = 0; b < blocks; ++b) {
      need(t, "a node block header");
      if (t.size() != 4) fail("expected 'entityDim entityTag parametric numNodesInBlock'");
      const long long dim = integer(t[0], "entityDim"), entity = integer(t[1], "entityTag");
      const long long parametric = integer(t[2], "parametric");
      if (dim < 0 || dim > 3) fail("entityDim must be 0..3");
      if (parametric != 0 && parametric != 1) fail("parametric must be 0 or 1");
      const long long m = count(t[3], "numNodesInBlock", limit());
      if (total + m > n) fail("the blocks have more nodes than the header's " + std::to_string(n));
      total += m;
      used_entities_.emplace(std::make_pair(static_cast<int>(dim), entity), line_);
      for (long long k = 0; k < m; ++k) {
        need(t, "a node tag");
        if (t.size() != 1) fail("expected one node tag per line");
        const long long node = tag(t[0], "node tag");
        add_node(node);
        seen_lo = seen_lo == 0 ? node : std::min(seen_lo, node);
        seen_hi = std::max(seen_hi, node);
      }
      const std::size_t coords = 3 + (parametric ? static_cast<std::size_t>(dim) : 0);
      for (long long k = 0; k < m; ++k) {
        need(t, "node coordinates");
        if (t.size() != coords) fail("expected " + std::to_string(coords) + " coordinates");
        for (const auto& c : t) coordinate(c);
      }
    }
    if (total != n)
      fail_at(header, "the blocks have " + std::to_string(total) + " nodes, the header says " + std::to_string(n));
    if (n > 0 && (seen_lo != lo || seen_hi != hi))
      fail_at(header, "node tags run from " + std::to_string(seen_lo) + " to " + std::to_string(seen_hi) +
                          ", the header says " + std::to_string(lo) + " to " + std::to_string(hi));
    expect_end("Nodes");
  }

  /// One element's type and node tags (tokens [first, first + nodes)).
  void element(long long type, const std::vector<std::string>& t, std::size_t first, int expect_dim) {
    const auto kind = element_kinds.find(type);
    if (kind == element_kinds.end()) fail("element type " + std::to_string(type) + " is not a Gmsh element type");
    if (expect_dim >= 0 && kind->second.dim != expect_dim)
      fail("element type " + std::to_string(type) + " has dimension " + std::to_string(kind->second.dim) +
           ", the block's entity " + std::to_string(expect_dim));
    if (t.size() != first + kind->second.nodes)
      fail("element type " + std::to_string(type) + " needs " + std::to_string(kind->second.nodes) +
           " node tags, the line has " +
           std::to_string(static_cast<long long>(t.size()) - static_cast<long long>(first)));
    const bool nodes_known = seen_.count("Nodes") > 0;
    for (std::size_t k = first; k < t.size(); ++k) {
      const long long node = tag(t[k], "node tag");
      if (!nodes_known)
        later_nodes_.emplace_back(node, line_);
      else if (!nodes_.count(node))
        fail("the element uses node " + std::to_string(node) + ", which the $Nodes section does not define");
    }
    surface_elements_ += kind->second.dim == 2;
  }
  void add_element(long long t) {
    if (!elements_.insert(t).second) fail("element " + std::to_string(t) + " is defined twice");
  }

  void elements_v2() {
    std::vector<std::string> t;
    need(t, "the element count");
    if (t.size() != 1) fail("expected the element count alone on its line");
    const long long n = count(t[0], "element count", limit());
    for (long long k = 0; k < n; ++k) {
      need(t, "element " + std::to_string(k + 1) + " of " + std::to_string(n));
      if (t.size() < 3) fail("an element needs 'tag type numTags tags... nodes...'");
      add_element(tag(t[0], "element tag"));
      const long long type = integer(t[1], "element type");
      const long long tags = count(t[2], "number of tags", 64);
      for (long long j = 0; j < tags && 3 + j < static_cast<long long>(t.size()); ++j) integer(t[3 + j], "a tag");
      element(type, t, 3 + static_cast<std::size_t>(tags), -1);
    }
    expect_end("Elements");
  }

  void elements_v4() {
    std::vector<std::string> t;
    need(t, "the elements header");
    if (t.size() != 4) fail("expected 'numEntityBlocks numElements minElementTag maxElementTag'");
    const long long blocks = count(t[0], "block count", limit());
    const long long n = count(t[1], "element count", limit());
    const int header = line_;
    long long total = 0;
    for (long long b = 0; b < blocks; ++b) {
      need(t, "an element block header");
      if (t.size() != 4) fail("expected 'entityDim entityTag elementType numElementsInBlock'");
      const long long dim = integer(t[0], "entityDim"), entity = integer(t[1], "entityTag");
      if (dim < 0 || dim > 3) fail("entityDim must be 0..3");
      const long long type = integer(t[2], "elementType");
      const long long m = count(t[3], "numElementsInBlock", limit());
      if (total + m > n) fail("the blocks have more elements than the header's " + std::to_string(n));
      total += m;
      used_entities_.emplace(std::make_pair(static_cast<int>(dim), entity), line_);
      for (long long k = 0; k < m; ++k) {
        need(t, "an element");
        add_element(tag(t[0], "element tag"));
        element(type, t, 1, static_cast<int>(dim));
      }
    }
    if (total != n)
      fail_at(header, "the blocks have " + std::to_string(total) + " elements, the header says " + std::to_string(n));
    expect_end("Elements");
  }

  void physical_names() {
    std::vector<std::string> t;
    need(t, "the physical name count");
    const long long n = count(t[0], "physical name count", limit());
    for (long long k = 0; k < n; ++k) {
      need(t, "a physical name");
      if (t.size() < 3) fail("expected 'dim tag \"name\"'");
      const long long dim = integer(t[0], "dimension");
      if (dim < 0 || dim > 3) fail("the dimension must be 0..3");
      integer(t[1], "physical tag");
      if (t[2].front() != '"' || t.back().back() != '"' || (t.size() == 3 && t[2].size() < 2))
        fail("the physical name must be in double quotes");
      for (const std::string& word : t)  // names reach messages, VTK files and summary.json
        if (const auto bad = invalid_utf8_offset(word))
          fail("the physical name is not UTF-8 text (" + describe_byte(word, *bad) + ")");
    }
    expect_end("PhysicalNames");
  }

  void entities() {
    std::vector<std::string> t;
    need(t, "the entity counts");
    if (t.size() != 4) fail("expected 'numPoints numCurves numSurfaces numVolumes'");
    long long counts[4];
    for (int d = 0; d < 4; ++d) counts[d] = count(t[d], "entity count", limit());
    for (int d = 0; d < 4; ++d)
      for (long long k = 0; k < counts[d]; ++k) {
        need(t, "an entity");
        // point: tag x y z numPhysicals tags...; others: tag 6 box values numPhysicals tags...
        // numBounding tags...
        const std::size_t box = d == 0 ? 3 : 6;
        if (t.size() < 2 + box) fail("an entity line is too short");
        const long long entity = integer(t[0], "entity tag");
        for (std::size_t c = 1; c <= box; ++c) coordinate(t[c]);
        std::size_t at = 1 + box;
        const long long physicals = count(t[at], "number of physical tags", 1e6);
        at += 1 + static_cast<std::size_t>(physicals);
        if (d > 0) {
          if (at >= t.size()) fail("an entity line is too short");
          const long long bounding = count(t[at], "number of bounding entities", 1e7);
          for (long long j = 0; j < bounding && at + 1 + j < t.size(); ++j) {
            const long long b = integer(t[at + 1 + j], "bounding entity tag");
            if (!entities_.count({d - 1, std::llabs(b)}))
              fail("bounding entity " + std::to_string(b) + " of dimension " + std::to_string(d - 1) +
                   " is not defined above");
          }
          at += 1 + static_cast<std::size_t>(bounding);
        }
        if (t.size() != at)
          fail("an entity line has " + std::to_string(t.size()) + " values, expected " + std::to_string(at));
        if (!entities_.insert({d, entity}).second) fail("entity " + std::to_string(entity) + " is defined twice");
      }
    expect_end("Entities");
  }

  std::string path_;
  std::ifstream in_;
  MeshLimits limits_;
  int line_ = 0;
  std::string version_;
  bool v4_ = false;
  std::set<std::string> seen_;
  std::unordered_set<long long> nodes_, elements_;
  std::vector<std::pair<long long, int>> later_nodes_;  // (node, line) used before $Nodes was read
  std::set<std::pair<int, long long>> entities_;
  std::map<std::pair<int, long long>, int> used_entities_;
  long long surface_elements_ = 0;
};

}  // namespace

void check_msh_structure(const std::string& path, const MeshLimits& limits) { MshChecker(path, limits).run(); }

}  // namespace iga
