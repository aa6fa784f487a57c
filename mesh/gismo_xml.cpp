#include "mesh/gismo_xml.hpp"

#include <tinyxml2.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <sstream>

#include "config/config_node.hpp"
#include "config/errors.hpp"
#include "config/utf8.hpp"
#include "config/text_excerpt.hpp"

namespace iga {

using tinyxml2::XMLElement;
using tinyxml2::XMLNode;

namespace {

/// Messages name the file and the element: "3p.xml:12: <coefs>: ...".
[[noreturn]] void fail_at(const std::string& source, const XMLElement* e, const std::string& message) {
  throw InputError(source + ":" + std::to_string(e->GetLineNum()) + ": <" + printable_excerpt(e->Name()) + ">: " + message);
}

/// Everything that is not an element, text or comment: a DTD (<!DOCTYPE ...>, where entities and
/// external references would be declared) or another declaration tinyxml2 keeps as "unknown".
void refuse_declarations(const std::string& source, const XMLNode* node) {
  for (const XMLNode* c = node->FirstChild(); c; c = c->NextSibling()) {
    if (c->ToUnknown())
      throw InputError(source + ":" + std::to_string(c->GetLineNum()) +
                       ": DTDs and other <!...> declarations are not accepted (no entities, no external references)");
    refuse_declarations(source, c);
  }
}

std::vector<std::string> tokens(const char* text) {
  std::istringstream in(text ? text : "");
  return {std::istream_iterator<std::string>(in), std::istream_iterator<std::string>()};
}

std::vector<double> numbers(const std::string& source, const XMLElement* e, const GismoXmlLimits& limits) {
  std::vector<double> out;
  const char* text = e->GetText();
  if (text && std::char_traits<char>::length(text) / 2 > limits.max_numbers)
    fail_at(source, e, "more than " + std::to_string(limits.max_numbers) + " numbers");
  for (const std::string& t : tokens(text)) {
    double x = 0.0;
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), x);
    if (ec != std::errc() || end != t.data() + t.size()) fail_at(source, e, quoted_excerpt(t) + " is not a number");
    if (!std::isfinite(x)) fail_at(source, e, quoted_excerpt(t) + " is not finite");
    out.push_back(x);
  }
  return out;
}

std::vector<int> integers(const std::string& source, const XMLElement* e, const GismoXmlLimits& limits) {
  std::vector<int> out;
  for (double x : numbers(source, e, limits)) {
    if (x != std::floor(x) || std::abs(x) > 1e9) fail_at(source, e, format_number(x) + " is not an index");
    out.push_back(static_cast<int>(x));
  }
  return out;
}

int int_attribute(const std::string& source, const XMLElement* e, const char* name) {
  int v = 0;
  const tinyxml2::XMLError err = e->QueryIntAttribute(name, &v);
  if (err == tinyxml2::XML_NO_ATTRIBUTE) fail_at(source, e, std::string("the attribute ") + name + " is missing");
  if (err != tinyxml2::XML_SUCCESS) fail_at(source, e, std::string("the attribute ") + name + " is not an integer");
  return v;
}

std::string type_of(const XMLElement* e) {
  const char* t = e->Attribute("type");
  return t ? t : "";
}

const XMLElement* child(const std::string& source, const XMLElement* parent, const char* name, const std::string& type = "") {
  for (const XMLElement* c = parent->FirstChildElement(name); c; c = c->NextSiblingElement(name))
    if (type.empty() || type_of(c) == type) return c;
  fail_at(source, parent, std::string("no <") + name + (type.empty() ? "" : " type=\"" + type + "\"") + "> inside");
}

/// <Basis type="TensorBSplineBasis2"> with its two <Basis type="BSplineBasis" index="0|1">.
void read_tensor_basis(const std::string& source, const XMLElement* basis, GismoPatch& p, const GismoXmlLimits& limits) {
  bool seen[2] = {false, false};
  for (const XMLElement* b = basis->FirstChildElement("Basis"); b; b = b->NextSiblingElement("Basis")) {
    if (type_of(b) != "BSplineBasis") fail_at(source, b, "type " + quoted_excerpt(type_of(b)) + " inside a tensor basis (expected BSplineBasis)");
    const int d = int_attribute(source, b, "index");
    if (d < 0 || d > 1) fail_at(source, b, "index " + std::to_string(d) + " (a surface patch has directions 0 and 1)");
    if (seen[d]) fail_at(source, b, "a second basis for direction " + std::to_string(d));
    seen[d] = true;
    const XMLElement* kv = child(source, b, "KnotVector");
    const int degree = int_attribute(source, kv, "degree");
    if (degree < 1 || degree > limits.max_degree)
      fail_at(source, kv, "degree " + std::to_string(degree) + " (must be 1.." + std::to_string(limits.max_degree) + ")");
    std::vector<double> knots = numbers(source, kv, limits);
    const auto n = static_cast<long>(knots.size()) - degree - 1;
    if (n < degree + 1)
      fail_at(source, kv, std::to_string(knots.size()) + " knots for degree " + std::to_string(degree) + " (need at least " +
                              std::to_string(2 * degree + 2) + ")");
    for (size_t i = 1; i < knots.size(); ++i)
      if (knots[i] < knots[i - 1]) fail_at(source, kv, "the knots decrease at position " + std::to_string(i));
    if (!(knots.back() > knots.front())) fail_at(source, kv, "the knot vector has zero length");
    p.degree[d] = degree;
    p.knots[d] = std::move(knots);
  }
  for (int d = 0; d < 2; ++d)
    if (!seen[d]) fail_at(source, basis, "no BSplineBasis with index " + std::to_string(d));
}

GismoPatch read_patch(const std::string& source, const XMLElement* g, const GismoXmlLimits& limits) {
  GismoPatch p;
  p.type = type_of(g);
  p.line = g->GetLineNum();
  if (g->Attribute("id")) p.id = int_attribute(source, g, "id");
  if (p.type != "TensorBSpline2" && p.type != "TensorNurbs2")
    fail_at(source, g, "type " + quoted_excerpt(p.type) + " is not supported (supported: TensorBSpline2, TensorNurbs2)");
  const bool rational = p.type == "TensorNurbs2";
  const XMLElement* basis = child(source, g, "Basis", rational ? "TensorNurbsBasis2" : "TensorBSplineBasis2");
  const XMLElement* weights = nullptr;
  if (rational) {
    weights = child(source, basis, "weights");
    basis = child(source, basis, "Basis", "TensorBSplineBasis2");
  }
  read_tensor_basis(source, basis, p, limits);
  const size_t nu = p.knots[0].size() - p.degree[0] - 1, nv = p.knots[1].size() - p.degree[1] - 1;
  const XMLElement* coefs = child(source, g, "coefs");
  const int dim = coefs->Attribute("geoDim") ? int_attribute(source, coefs, "geoDim") : 2;
  if (dim != 2 && dim != 3) fail_at(source, coefs, "geoDim " + std::to_string(dim) + " (planar domains: 2, or 3 with z = 0)");
  const std::vector<double> c = numbers(source, coefs, limits);
  if (c.size() != nu * nv * dim)
    fail_at(source, coefs, "the knot vectors need " + std::to_string(nu) + " x " + std::to_string(nv) + " control points of " +
                               std::to_string(dim) + " coordinates = " + std::to_string(nu * nv * dim) + " numbers (got " +
                               std::to_string(c.size()) + ")");
  for (size_t i = 0; i < nu * nv; ++i) {
    if (dim == 3 && limits.planar && c[dim * i + 2] != 0.0)
      fail_at(source, coefs, "control point " + std::to_string(i) + " has z = " + format_number(c[dim * i + 2]) +
                                 " (planar domains need z = 0)");
    p.control_points.emplace_back(c[dim * i], c[dim * i + 1]);
    p.z.push_back(dim == 3 ? c[dim * i + 2] : 0.0);
  }
  if (weights) {
    p.weights = numbers(source, weights, limits);
    if (p.weights.size() != nu * nv)
      fail_at(source, weights, "need one weight per control point: " + std::to_string(nu * nv) + " (got " +
                                   std::to_string(p.weights.size()) + ")");
    for (size_t i = 0; i < p.weights.size(); ++i)
      if (!(p.weights[i] > 0.0))
        fail_at(source, weights, "weights must be positive (weight " + std::to_string(i) + " is " + format_number(p.weights[i]) + ")");
  }
  return p;
}

/// <patches type="id_range">first last</patches> or <patches type="id_index">id id ...</patches>.
std::vector<int> patch_ids(const std::string& source, const XMLElement* patches, const GismoXmlLimits& limits) {
  const std::string type = type_of(patches);
  const std::vector<int> v = integers(source, patches, limits);
  if (type == "id_index") return v;
  if (type != "id_range") fail_at(source, patches, "type " + quoted_excerpt(type) + " (supported: id_range, id_index)");
  if (v.size() != 2 || v[1] < v[0]) fail_at(source, patches, "an id_range needs two ids, first <= last");
  if (static_cast<long>(v[1]) - v[0] >= limits.max_patches)
    fail_at(source, patches, "more than " + std::to_string(limits.max_patches) + " patches");
  std::vector<int> ids;
  for (int i = v[0]; i <= v[1]; ++i) ids.push_back(i);
  return ids;
}

GismoSide side_at(const std::string& source, const XMLElement* e, int patch, int side, size_t patches) {
  if (patch < 0 || patch >= static_cast<int>(patches))
    fail_at(source, e, "patch index " + std::to_string(patch) + " (the multipatch has patches 0.." + std::to_string(patches - 1) + ")");
  if (side < 1 || side > 4) fail_at(source, e, "side " + std::to_string(side) + " (sides are 1 west, 2 east, 3 south, 4 north)");
  return {patch, side};
}

std::string read_limited(const std::string& path, const GismoXmlLimits& limits) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw InputError(path + ": cannot read the geometry file");
  const auto size = std::filesystem::file_size(path, ec);
  if (ec) throw InputError(path + ": cannot read the geometry file");
  if (size > limits.max_bytes)
    throw InputError(path + ": " + std::to_string(size) + " bytes, more than the limit of " + std::to_string(limits.max_bytes) +
                     " for a geometry file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot read the geometry file");
  std::string text(size, '\0');
  in.read(text.data(), static_cast<std::streamsize>(size));
  if (in.gcount() != static_cast<std::streamsize>(size)) throw InputError(path + ": cannot read the geometry file");
  return text;
}

// Corners (u, v) in {0, 1}² of a bilinear patch: p00 p10 p01 p11 are control points 0 1 2 3.
std::array<int, 2> side_corners(int side) {
  switch (side) {
    case 1: return {0, 2};  // west, u = 0
    case 2: return {1, 3};  // east, u = 1
    case 3: return {0, 1};  // south, v = 0
    default: return {2, 3}; // north, v = 1
  }
}

const char* side_name(int side) {
  static const char* names[] = {"", "1 (west)", "2 (east)", "3 (south)", "4 (north)"};
  return names[side];
}

}  // namespace

std::string GismoPatch::describe() const {
  return "Geometry id " + std::to_string(id) + " (line " + std::to_string(line) + ")";
}

GismoMultiPatch read_gismo_xml(const std::string& path, const GismoXmlLimits& limits) {
  return parse_gismo_xml(read_limited(path, limits), path, limits);
}

GismoMultiPatch parse_gismo_xml(const std::string& text, const std::string& path, const GismoXmlLimits& limits) {
  if (text.size() > limits.max_bytes)
    throw InputError(path + ": " + std::to_string(text.size()) + " bytes, more than the limit of " +
                     std::to_string(limits.max_bytes) + " for a geometry file");
  // XML is UTF-8 here (tinyxml2 reads no other encoding); the boundary names reach outputs.
  if (const auto bad = invalid_utf8_offset(text))
    throw InputError(path + ":" + std::to_string(1 + std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(*bad), '\n')) +
                     ": " + describe_byte(text, *bad) + " is not UTF-8 (a G+Smo file is UTF-8 text)");
  GismoMultiPatch mp;
  mp.source = path;
  tinyxml2::XMLDocument doc(true, tinyxml2::PRESERVE_WHITESPACE);
  // tinyxml2 knows only the five predefined entities and character references, and caps the
  // element depth; a DTD is kept as an "unknown" node, refused below.
  if (doc.Parse(text.data(), text.size()) != tinyxml2::XML_SUCCESS)
    throw InputError(path + ":" + std::to_string(doc.ErrorLineNum()) + ": not well-formed XML (" + doc.ErrorName() + ")");
  refuse_declarations(path, &doc);
  const XMLElement* root = doc.RootElement();
  if (!root) throw InputError(path + ": no XML element");
  if (std::string(root->Name()) != "xml") fail_at(path, root, "a G+Smo file has the root element <xml>");

  std::map<int, const XMLElement*> geometries;
  int count = 0;
  for (const XMLElement* g = root->FirstChildElement("Geometry"); g; g = g->NextSiblingElement("Geometry")) {
    if (++count > limits.max_patches) fail_at(path, g, "more than " + std::to_string(limits.max_patches) + " geometries");
    const int id = g->Attribute("id") ? int_attribute(path, g, "id") : count - 1;
    if (!geometries.emplace(id, g).second) fail_at(path, g, "a second Geometry with id " + std::to_string(id));
  }
  const XMLElement* multi = root->FirstChildElement("MultiPatch");
  if (multi && multi->NextSiblingElement("MultiPatch"))
    fail_at(path, multi->NextSiblingElement("MultiPatch"), "a second MultiPatch (a file describes one domain)");
  if (!multi) {
    if (geometries.empty()) fail_at(path, root, "no <Geometry> and no <MultiPatch>");
    for (const auto& [id, g] : geometries) mp.patches.push_back(read_patch(path, g, limits));
    return mp;
  }
  const int dim = multi->Attribute("parDim") ? int_attribute(path, multi, "parDim") : 2;
  if (dim != 2) fail_at(path, multi, "parDim " + std::to_string(dim) + " (planar domains: 2)");
  const XMLElement* patches = child(path, multi, "patches");
  std::set<int> used;
  for (int id : patch_ids(path, patches, limits)) {
    const auto it = geometries.find(id);
    if (it == geometries.end()) fail_at(path, patches, "no Geometry with id " + std::to_string(id));
    if (!used.insert(id).second) fail_at(path, patches, "Geometry id " + std::to_string(id) + " listed twice");
    mp.patches.push_back(read_patch(path, it->second, limits));
  }
  if (mp.patches.empty()) fail_at(path, patches, "no patches");
  if (const XMLElement* e = multi->FirstChildElement("interfaces")) {
    if (e->NextSiblingElement("interfaces")) fail_at(path, e->NextSiblingElement("interfaces"), "a second <interfaces>");
    mp.has_interfaces = true;
    // Per interface: patch side patch side, then the direction map (2) and orientation (2).
    const std::vector<int> v = integers(path, e, limits);
    if (v.size() % 8 != 0)
      fail_at(path, e, std::to_string(v.size()) + " numbers; each interface is 8: patch side patch side, direction map (2), orientation (2)");
    for (size_t i = 0; i < v.size(); i += 8)
      mp.interfaces.push_back({side_at(path, e, v[i], v[i + 1], mp.patches.size()),
                               side_at(path, e, v[i + 2], v[i + 3], mp.patches.size()), e->GetLineNum()});
  }
  for (const XMLElement* e = multi->FirstChildElement("boundary"); e; e = e->NextSiblingElement("boundary")) {
    const std::vector<int> v = integers(path, e, limits);
    if (v.size() % 2 != 0) fail_at(path, e, std::to_string(v.size()) + " numbers; each boundary side is 2: patch side");
    std::vector<GismoSide> sides;
    for (size_t i = 0; i < v.size(); i += 2) sides.push_back(side_at(path, e, v[i], v[i + 1], mp.patches.size()));
    mp.boundary.emplace_back(e->Attribute("name") ? e->Attribute("name") : "", std::move(sides));
    mp.boundary_lines.push_back(e->GetLineNum());
  }
  return mp;
}

PlanarMesh bilinear_patch_mesh(const GismoMultiPatch& mp) {
  const std::string& src = mp.source;
  double size = 0.0;
  for (size_t k = 0; k < mp.patches.size(); ++k) {
    const GismoPatch& p = mp.patches[k];
    const std::string where = src + ": patch " + std::to_string(k) + ", " + p.describe() + ": ";
    // Degree 1 with knots a a b b: the four control points are the corners.
    const auto bilinear_knots = [](const std::vector<double>& t) { return t.size() == 4 && t[0] == t[1] && t[2] == t[3]; };
    if (p.degree[0] != 1 || p.degree[1] != 1 || !bilinear_knots(p.knots[0]) || !bilinear_knots(p.knots[1]))
      throw InputError(where + "degree (" + std::to_string(p.degree[0]) + ", " + std::to_string(p.degree[1]) + ") with " +
                       std::to_string(p.knots[0].size()) + " and " + std::to_string(p.knots[1].size()) +
                       " knots is not bilinear: a multipatch domain file must hold bilinear patches (degree 1, knots 0 0 1 1), "
                       "the corners of a mesh of quadrilaterals (one patch of any degree: space bspline)");
    if (!p.weights.empty() && *std::max_element(p.weights.begin(), p.weights.end()) !=
                                  *std::min_element(p.weights.begin(), p.weights.end()))
      throw InputError(where + "a rational patch with unequal weights is not bilinear: a multipatch domain file must hold bilinear patches");
    for (const auto& x : p.control_points) size = std::max(size, x.cwiseAbs().maxCoeff());
  }
  const double tol = 1e-10 * std::max(size, 1.0);
  PlanarMesh mesh;
  mesh.source = src;
  std::vector<std::array<int, 4>> corner_vertex;  // per patch, vertex of control point 0..3
  for (size_t k = 0; k < mp.patches.size(); ++k) {
    const GismoPatch& p = mp.patches[k];
    std::array<int, 4> ids{};
    for (int c = 0; c < 4; ++c) {
      const Eigen::Vector2d& x = p.control_points[c];
      int found = -1;
      for (int v = 0; v < static_cast<int>(mesh.vertices.size()) && found < 0; ++v)
        if ((mesh.vertices[v] - x).cwiseAbs().maxCoeff() <= tol) found = v;
      if (found < 0) {
        found = static_cast<int>(mesh.vertices.size());
        mesh.vertices.push_back(x);
      }
      ids[c] = found;
    }
    corner_vertex.push_back(ids);
    mesh.cells.push_back({ids[0], ids[1], ids[3], ids[2]});
    mesh.cell_origins.push_back("patch " + std::to_string(k) + ", " + p.describe());
  }
  // The sides by their (unordered) corner vertices, to check the file's topology against the geometry.
  std::map<std::pair<int, int>, std::vector<GismoSide>> sides_at;
  const auto key = [&](const GismoSide& s) {
    const auto c = side_corners(s.side);
    const int a = corner_vertex[s.patch][c[0]], b = corner_vertex[s.patch][c[1]];
    return std::make_pair(std::min(a, b), std::max(a, b));
  };
  const auto describe_side = [&](const GismoSide& s) {
    return "patch " + std::to_string(s.patch) + " side " + side_name(s.side);
  };
  for (int k = 0; k < static_cast<int>(mp.patches.size()); ++k)
    for (int s = 1; s <= 4; ++s) sides_at[key({k, s})].push_back({k, s});
  std::set<std::pair<int, int>> listed;
  for (const GismoInterface& i : mp.interfaces) {
    const std::string at = src + ":" + std::to_string(i.line) + ": <interfaces>: ";
    if (key(i.a) != key(i.b))
      throw InputError(at + describe_side(i.a) + " and " + describe_side(i.b) + " do not have the same corners");
    if (i.a.patch == i.b.patch && i.a.side == i.b.side)
      throw InputError(at + describe_side(i.a) + " is joined to itself");
    listed.insert(key(i.a));
  }
  for (const auto& [k, sides] : sides_at) {
    if (sides.size() > 2)
      throw InputError(src + ": " + describe_side(sides[0]) + ", " + describe_side(sides[1]) + " and " + describe_side(sides[2]) +
                       " share their corners (a side of more than two patches)");
    if (sides.size() == 2 && mp.has_interfaces && !listed.count(k))
      throw InputError(src + ": " + describe_side(sides[0]) + " and " + describe_side(sides[1]) +
                       " have the same corners but <interfaces> does not list them (the patches would not be joined)");
  }
  for (size_t b = 0; b < mp.boundary.size(); ++b) {
    const auto& [name, sides] = mp.boundary[b];
    for (const GismoSide& s : sides) {
      if (sides_at[key(s)].size() != 1)
        throw InputError(src + ":" + std::to_string(mp.boundary_lines[b]) + ": <boundary>: " + describe_side(s) +
                         " is shared with another patch, not on the boundary");
      if (name.empty()) continue;
      const auto c = side_corners(s.side);
      mesh.boundary_groups[name].push_back({corner_vertex[s.patch][c[0]], corner_vertex[s.patch][c[1]]});
    }
  }
  orient_cells_counterclockwise(mesh);
  return mesh;
}

const GismoPatch& single_gismo_patch(const GismoMultiPatch& mp, const std::string& space) {
  if (mp.patches.size() != 1)
    throw InputError(mp.source + ": " + std::to_string(mp.patches.size()) + " patches: the " + space +
                     " space takes a single patch (multipatch domains: space g1 or g1_4split)");
  if (!mp.interfaces.empty())
    throw InputError(mp.source + ":" + std::to_string(mp.interfaces.front().line) +
                     ": <interfaces>: the " + space + " space takes a single patch without interfaces (no periodic sides)");
  return mp.patches.front();
}

}  // namespace iga
