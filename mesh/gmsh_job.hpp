#pragma once
/// @file
/// One piece of Gmsh work (read a .msh or .stl, mesh a .geo, mesh a polygon) as the Gmsh worker
/// process receives it, and the byte encodings of the job and of its result that travel through
/// its pipes. A job gives a planar mesh, or with `surface` a triangle mesh in 3D.

#include <string>
#include <string_view>
#include <vector>

#include "mesh/mesh_limits.hpp"
#include "mesh/mesh_polygon.hpp"
#include "mesh/planar_mesh.hpp"
#include "mesh/read_surface_mesh.hpp"

namespace iga {

struct GmshJob {
  enum Kind : char { read_msh = 'm', mesh_geo = 'g', mesh_polygon = 'p', read_stl = 's' };
  Kind kind = read_msh;
  std::string path;                           ///< the .msh, .geo or .stl file (read_msh, mesh_geo, read_stl)
  std::string source;                         ///< names the input in messages
  double mesh_size = 0.0;                     ///< mesh_geo (0: the file's own sizes), mesh_polygon
  bool recombine = false;                     ///< quadrilaterals (Mesh.RecombineAll)
  bool surface = false;                       ///< the result is a triangle mesh in 3D (read_stl always)
  PolygonDomain polygon;                      ///< mesh_polygon
  std::vector<std::string> readable_folders;  ///< what the worker may read (besides its libraries)
  MeshLimits limits;
};

/// Runs `job` with the Gmsh SDK in this process (the worker's side; see gmsh_worker.hpp; only the
/// worker links the Gmsh library, the encodings below live in gmsh_job_codec.cpp). For
/// mesh_geo with a mesh size, the element estimate over the bounding box of the surfaces is
/// checked before meshing.
PlanarMesh run_gmsh_job_here(const GmshJob& job);

/// The same for surface jobs: the triangles of the model in 3D (see gmsh_model_surface.hpp). For
/// mesh_geo with a mesh size, the estimate uses the surfaces' bounding boxes in 3D.
SurfaceMeshFile run_gmsh_surface_job_here(const GmshJob& job);

std::string encode_job(const GmshJob& job);
/// Throws std::runtime_error on a malformed encoding.
GmshJob decode_job(std::string_view bytes);

/// A result is 'M' + an encoded mesh, or 'E' + the message of an InputError.
std::string encode_mesh_result(const PlanarMesh& mesh);
std::string encode_error_result(const std::string& message);
/// A surface result is 'S' + an encoded SurfaceMeshFile (points, triangles, their Gmsh names).
std::string encode_surface_result(const SurfaceMeshFile& mesh);
/// Throws std::runtime_error on a malformed encoding (a worker that died while writing).
PlanarMesh decode_mesh(std::string_view bytes, const std::string& source);
SurfaceMeshFile decode_surface(std::string_view bytes, const std::string& source);

}  // namespace iga
