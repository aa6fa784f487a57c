#pragma once
/// @file
/// ParaView output through VTK's XML writers: one .vtu per level and a .pvd collection.
///
/// How the elements are drawn is element_drawing.hpp's job: elements whose functions are single
/// polynomials of the space's degree (lagrange_cells.hpp) become one VTK Lagrange triangle /
/// quadrilateral of that degree each, sampled at its nodes; the others (macro-elements, polynomial
/// only piece by piece, and non-polynomial bases) Lagrange cells of that degree on a uniform
/// subdivision of the element (or, asked for, the linear sub-cells of Space::sample_cell). Points
/// shared between elements are written once. This file evaluates the fields on that drawing. Values
/// are computed in double precision and stored in single precision (7 digits, far below what a
/// picture resolves; the error field is stored itself, not left to a difference of two rounded fields).

#include <Eigen/Core>
#include <functional>
#include <string>
#include <utility>
#include <vector>

class vtkXMLWriter;

#include "assembly/fields.hpp"
#include "solver/study.hpp"
#include "spaces/space.hpp"

namespace iga {

struct VtkFieldOptions {
  int samples = 8;  ///< samples per element edge where linear sub-cells are drawn (Space::sample_cell)
  /// Draw single-polynomial elements as Lagrange cells (false: always linear sub-cells).
  bool lagrange = true;
  /// With `lagrange`: elements that are not single polynomials are drawn as divisions² Lagrange
  /// cells of the space's degree interpolating u_h on a uniform subdivision of the element
  /// (1: one cell per element; 0: linear sub-cells).
  int divisions = 1;
  /// Exact solution, if known: adds point fields `u_exact` and `error` (u - u_exact), and with its
  /// derivatives the cell fields `error_l2`, `error_h1`, `error_h2`. Called from several threads
  /// at once, so it must be thread-safe (as every ScalarField).
  ExactSolution exact;
  /// The same on a surface in 3D (spaces with ambient_dimension() == 3), used instead of `exact`.
  std::function<double(const Eigen::Vector3d&)> exact3;
  /// Adds the point field `laplace_u` (for biharmonic problems).
  bool laplacian = false;
  /// Further cell fields, one value per element (e.g. the estimator η_K, marked elements).
  std::vector<std::pair<std::string, std::vector<double>>> element_fields;
  /// Further functions of the space (coefficient vectors) as point fields of their values, e.g.
  /// the eigenmodes mode_1, mode_2, ... of an eigenproblem.
  std::vector<std::pair<std::string, Eigen::VectorXd>> point_functions;
  /// Vector fields in 3D whose components are functions of the space (a shell's displacement:
  /// coefficients in blocks of dimension(), x then y then z), as 3-component point fields that
  /// ParaView warps by.
  std::vector<std::pair<std::string, Eigen::VectorXd>> vector_functions;
  VtkCompression compression = VtkCompression::lz4;
};

/// Set `writer`'s compressor: LZ4 at its strongest (still fast), zlib at its fastest, or none.
void set_vtk_compression(vtkXMLWriter& writer, VtkCompression compression);

/// Write the discrete function sum_i coefficients(i) N_i as an unstructured grid with point fields
/// `u`, `grad_u` (3 components, z = 0 in the plane; on a surface in 3D the points are the surface's
/// and grad_u its surface gradient), normals (`Normals`, the active normals, on a surface in 3D;
/// `warp_normal`, the unit normal of the graph z = u for Warp By Scalar with factor 1, in the plane),
/// the cell field `element` and the optional fields of `options`.
/// Returns true when the elements were drawn as Lagrange cells of the space's degree.
/// Throws std::runtime_error if the file cannot be written.
bool write_solution_vtu(const Space& space, const Eigen::VectorXd& coefficients, const VtkFieldOptions& options,
                        const std::string& filename);

/// Write the outline of every element (its boundary through the element map, `samples` points per
/// edge) as closed poly-lines with a cell field `element`: the mesh, including where it was refined.
void write_mesh_vtu(const Space& space, int samples, const std::string& filename,
                    VtkCompression compression = VtkCompression::lz4);

/// Write a ParaView collection listing `datasets` (paths relative to the .pvd) as time steps 0, 1, ...
void write_pvd(const std::vector<std::string>& datasets, const std::string& filename);

}  // namespace iga
