#include "node_frame.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace sketchlab::soapfilm {

NodeFrame fit_node_frame(const std::vector<Vec3>& directions, const NodeFrameParams& params) {
  NodeFrame frame;
  Mat3 m = Mat3::Zero();
  int k = 0;
  for (const Vec3& d : directions) {
    const double len = d.norm();
    if (!(len > 0.0) || !std::isfinite(len)) continue;
    const Vec3 u = d / len;
    m += u * u.transpose();
    ++k;
  }
  if (k < 2) return frame;
  Eigen::SelfAdjointEigenSolver<Mat3> eig(m);
  const Vec3 lambda = eig.eigenvalues();  // ascending
  // The tangents must span a plane: the middle eigenvalue is the spread
  // across the main direction (0 for collinear tangents).
  if (!(lambda(1) > 1e-6 * k)) return frame;
  Vec3 n = eig.eigenvectors().col(0).normalized();
  // Deterministic sign: largest component positive.
  int i = 0;
  n.cwiseAbs().maxCoeff(&i);
  if (n(i) < 0.0) n = -n;
  frame.normal = n;
  frame.defined = true;
  frame.fit_error = std::sqrt(std::max(lambda(0), 0.0) / k);
  for (const Vec3& d : directions)
    if (d.norm() > 0.0) frame.max_offset = std::max(frame.max_offset, std::abs(n.dot(d.normalized())));
  frame.sharp = frame.fit_error > params.sharp_error ||
                frame.max_offset > std::cos(0.5 * 3.141592653589793 - params.sharp_angle);
  return frame;
}

}  // namespace sketchlab::soapfilm
