#pragma once
/// @file
/// G+Smo's XML geometry files: a `<MultiPatch>` of `TensorBSpline2` / `TensorNurbs2` patches with
/// its `<interfaces>` and `<boundary>`, or a file of one `<Geometry>`. Parsed with tinyxml2 (no
/// DTDs, so no entity expansion and no external entities; a size and element-depth limit), then
/// checked: knot vectors, control point and weight counts, finite numbers, planar control points.
/// What a space makes of the patches is its own business: bilinear_patch_mesh() turns bilinear
/// patches into a PlanarMesh (G1 spaces), single_gismo_patch() hands one patch to the B-spline
/// space. Every failure is an InputError naming the file and the XML element with its line.

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "config/errors.hpp"
#include "mesh/planar_mesh.hpp"

namespace iga {

/// One tensor-product patch as the file gives it.
struct GismoPatch {
  int id = 0;            ///< the Geometry element's id attribute
  int line = 0;          ///< line of the Geometry element
  std::string type;      ///< TensorBSpline2 or TensorNurbs2
  std::array<int, 2> degree{};                 ///< (u, v)
  std::array<std::vector<double>, 2> knots;    ///< full knot vectors (u, v), as in the file
  std::vector<Eigen::Vector2d> control_points; ///< numbered i + j * n_u (u fastest, as G+Smo stores them)
  std::vector<double> z;                       ///< their z (geoDim 3; zeros for geoDim 2)
  std::vector<double> weights;                 ///< TensorNurbs2 only (one per control point), else empty
  /// "patch 2 (Geometry id 7, line 40)", for messages.
  std::string describe() const;
};

/// Sides as G+Smo numbers them: 1 west (u = 0), 2 east (u = 1), 3 south (v = 0), 4 north (v = 1).
struct GismoSide {
  int patch = 0;  ///< index into GismoMultiPatch::patches
  int side = 0;   ///< 1..4
};

struct GismoInterface {
  GismoSide a, b;
  int line = 0;  ///< line of the <interfaces> element
};

struct GismoMultiPatch {
  std::string source;               ///< the file, for messages
  std::vector<GismoPatch> patches;  ///< in the order of <patches> (interfaces refer to these indices)
  bool has_interfaces = false;      ///< the file has an <interfaces> element
  std::vector<GismoInterface> interfaces;
  /// <boundary> sides by the element's `name` attribute (unnamed: ""), each with its line.
  std::vector<std::pair<std::string, std::vector<GismoSide>>> boundary;
  std::vector<int> boundary_lines;
};

/// Limits on what one XML file may hold before it is refused.
struct GismoXmlLimits {
  std::size_t max_bytes = std::size_t{16} << 20;  ///< file size
  int max_patches = 10000;
  std::size_t max_numbers = 4000000;  ///< numbers in one element (knots, coefficients, weights)
  int max_degree = 20;
  /// Planar domains refuse control points with z != 0; surface patches in 3D read them (GismoPatch::z).
  bool planar = true;
};

/// Read and check `path` (see the file comment). A file of one or more `<Geometry>` elements and no
/// `<MultiPatch>` is read as those patches, without interfaces.
GismoMultiPatch read_gismo_xml(const std::string& path, const GismoXmlLimits& limits = {});

/// The same for the file's text; `source` names it in messages.
GismoMultiPatch parse_gismo_xml(const std::string& text, const std::string& source, const GismoXmlLimits& limits = {});

/// The patches as a mesh of quadrilaterals, for spaces built on bilinear patches (G1): every patch
/// must be bilinear (degree 1 in both directions, no interior knots, equal weights if rational);
/// the listed interfaces must be sides with the same corners, no two patches may share a side
/// that <interfaces> does not list, and a <boundary> side must lie on no other patch. Corners within
/// 1e-10 x the domain size are one vertex; cells are p00, p10, p11, p01 (reversed where clockwise,
/// keeping p00). Named <boundary> elements become boundary groups.
PlanarMesh bilinear_patch_mesh(const GismoMultiPatch& multipatch);

/// The one patch of a single-patch file (refuses several patches and interfaces, naming `space`).
const GismoPatch& single_gismo_patch(const GismoMultiPatch& multipatch, const std::string& space);

/// Runs `build` (a map made from `patch` of the file `path`); an std::invalid_argument or
/// InputError it throws is rethrown as InputError "path: <patch.describe()>: message".
template <class Build>
auto build_from_gismo_patch(const std::string& path, const GismoPatch& patch, Build&& build) {
  try {
    return build();
  } catch (const std::invalid_argument& e) {
    throw InputError(path + ": " + patch.describe() + ": " + e.what());
  } catch (const InputError& e) {
    throw InputError(path + ": " + patch.describe() + ": " + e.what());
  }
}

}  // namespace iga
