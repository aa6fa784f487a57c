#pragma once
/// @file
/// The records of an OFF file (header, counts, vertices, faces), shared by the planar, triangle
/// surface and quad surface readers; each reader decides which face sizes it accepts.

#include <Eigen/Core>

#include <functional>
#include <string>
#include <vector>

#include "mesh/text_line_reader.hpp"

namespace iga {

/// Vertices and faces of an OFF file, each with the line it came from.
struct OffRecords {
  std::vector<Eigen::Vector3d> points;
  std::vector<int> point_lines;
  std::vector<std::vector<int>> faces;  ///< 0-based vertex indices, checked against the vertex count
  std::vector<int> face_lines;
};

/// Reads the whole file through `reader` ("OFF", the counts on the header line or the next one,
/// then exactly that many vertices and faces; colour values after a face's indices are ignored).
/// `face_size_error(n)` is empty when a face of n vertices is accepted, else the message to fail
/// with. Errors name the file and line (InputError).
OffRecords read_off_records(TextLineReader& reader, const std::function<std::string(long)>& face_size_error);

}  // namespace iga
