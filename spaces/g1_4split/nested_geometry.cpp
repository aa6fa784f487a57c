#include "spaces/g1_4split/nested_geometry.hpp"

namespace iga {

void NestedGeometry::face(int f, Path& path, const Eigen::VectorXd*& x, const Eigen::VectorXd*& y) const {
  if (levels_ == 0) {
    x = &level0_.x[f];
    y = &level0_.y[f];
    return;
  }
  if (static_cast<int>(path.face.size()) != levels_) {
    path.face.assign(levels_, -1);
    path.x.assign(levels_, {});
    path.y.assign(levels_, {});
  }
  // path.face[l - 1] is the ancestor on level l: f >> 2 (levels - l).
  bool same = true;  // the ancestors so far are the ones kept
  for (int l = 1; l <= levels_; ++l) {
    const long long a = static_cast<long long>(f) >> (2 * (levels_ - l));
    if (same && path.face[l - 1] == a) continue;
    same = false;
    const Eigen::VectorXd& px = l == 1 ? level0_.x[a >> 2] : path.x[l - 2];
    const Eigen::VectorXd& py = l == 1 ? level0_.y[a >> 2] : path.y[l - 2];
    path.x[l - 1] = subdivided_face(b_, px, static_cast<int>(a & 3));
    path.y[l - 1] = subdivided_face(b_, py, static_cast<int>(a & 3));
    path.face[l - 1] = a;
  }
  x = &path.x[levels_ - 1];
  y = &path.y[levels_ - 1];
}

}  // namespace iga
