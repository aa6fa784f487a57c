#include "mesh/off_records.hpp"

#include <algorithm>

namespace iga {

OffRecords read_off_records(TextLineReader& reader, const std::function<std::string(long)>& face_size_error) {
  std::vector<std::string> t;
  if (!reader.next(t) || t[0] != "OFF") reader.fail("expected the header 'OFF'");
  // The counts may follow the header on the same line.
  std::vector<std::string> counts(t.begin() + 1, t.end());
  if (counts.empty() && !reader.next(counts)) reader.fail("expected 'vertices faces edges' counts");
  if (counts.size() < 2 || counts.size() > 3) reader.fail("expected 'vertices faces edges' counts");
  const long nv = reader.integer(counts[0]), nf = reader.integer(counts[1]);
  if (nv < 0 || nf < 0) reader.fail("negative counts");
  OffRecords records;
  for (long v = 0; v < nv; ++v) {
    if (!reader.next(t))
      reader.fail("the file ends after " + std::to_string(v) + " of " + std::to_string(nv) + " vertices");
    if (t.size() != 3) reader.fail("a vertex needs 'x y z'");
    records.points.emplace_back(reader.number(t[0]), reader.number(t[1]), reader.number(t[2]));
    records.point_lines.push_back(reader.line);
  }
  for (long f = 0; f < nf; ++f) {
    if (!reader.next(t))
      reader.fail("the file ends after " + std::to_string(f) + " of " + std::to_string(nf) + " faces");
    const long n = reader.integer(t[0]);
    if (const std::string error = face_size_error(n); !error.empty()) reader.fail(error);
    if (static_cast<long>(t.size()) < n + 1)
      reader.fail("a face lists fewer vertices than its count " + std::to_string(n));
    std::vector<int> face;
    for (long k = 1; k <= n; ++k) {  // tokens after the n indices are colour values
      const long id = reader.integer(t[k]);
      if (id < 0 || id >= nv)
        reader.fail("face vertex " + std::to_string(id) + " does not exist (" + std::to_string(nv) +
                    " vertices; OFF indices are 0-based)");
      face.push_back(static_cast<int>(id));
    }
    records.faces.push_back(std::move(face));
    records.face_lines.push_back(reader.line);
  }
  if (reader.next(t)) reader.fail("unexpected data after the " + std::to_string(nf) + " faces");
  return records;
}

}  // namespace iga
