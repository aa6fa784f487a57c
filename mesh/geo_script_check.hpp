#pragma once
/// @file
/// A static check of a Gmsh `.geo` script before Gmsh runs it. A `.geo` is a program: Gmsh's
/// language can run shell commands, read and write files, sleep, end the process and loop without
/// bound. Only geometry and mesh statements pass (see the .cpp for the lists); the Gmsh worker
/// (gmsh_worker.hpp) confines whatever slips through with time, memory and system-call limits.

#include <filesystem>
#include <vector>

#include "mesh/mesh_limits.hpp"

namespace iga {

/// Refuses, with an InputError "<file>:<line>: ..." naming the statement:
///  - a word that acts outside the geometry anywhere in the text (SystemCall, System, Save, Merge,
///    Print, Exit, Abort, Sleep, OnelabRun, Plugin, CreateDir, ShapeFromFile, GetEnv, ...);
///  - a statement that is neither an assignment nor on the allow-list of geometry and mesh
///    statements (Point, Line, Curve Loop, Plane Surface, Physical ..., Transfinite, Field, For,
///    If, ...); options other than Mesh.* and Geometry.*; Printf to a file; Delete of anything but
///    an entity list; Field types that read files or run programs;
///  - an Include that is not a literal path to a file inside one of `include_roots` (or whose
///    script is refused in turn, or that includes itself);
///  - a For loop or {a:b:step} range whose bounds evaluate (numbers and variables set to numbers)
///    to more than limits.max_loop_iterations iterations, a zero step, or non-finite bounds.
/// Unreadable files and unterminated strings or comments are refused as well. The option file
/// "<file>.opt", which Gmsh runs when it opens <file>, is checked the same way when it exists.
/// The script and its option file, links resolved, must lie inside one of `include_roots` too (a
/// link beside the mesh pointing elsewhere is refused before it is read).
/// Returns every file checked (the script, its Includes, the option file): what Gmsh will read.
std::vector<std::filesystem::path> check_geo_script(const std::filesystem::path& file,
                                                    const std::vector<std::filesystem::path>& include_roots,
                                                    const MeshLimits& limits = {});

/// The largest mesh size the script gives a point (`Point(n) = {x, y, z, lc}`, `MeshSize {..} = lc`,
/// `Characteristic Length {..} = lc`, in the script, its Includes and its option file), read by
/// the same static pass as check_geo_script. +inf when there is no bound: no point has a size, a
/// point has none, a size cannot be evaluated before Gmsh runs (a loop variable, a function call),
/// or the pass refuses the script. The element estimate before meshing uses it.
double geo_script_largest_point_size(const std::filesystem::path& file,
                                     const std::vector<std::filesystem::path>& include_roots,
                                     const MeshLimits& limits = {});

}  // namespace iga
