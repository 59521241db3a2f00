#include "node_frame.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numbers>

namespace sketchlab::soapfilm {
namespace {

std::vector<Vec3> unit(const std::vector<Vec3>& in) {
  std::vector<Vec3> out;
  for (const Vec3& d : in) {
    const double len = d.norm();
    if (len > 0.0 && std::isfinite(len)) out.push_back(d / len);
  }
  return out;
}

double largest_cross(const std::vector<Vec3>& d) {
  double best = 0.0;
  for (std::size_t i = 0; i < d.size(); ++i)
    for (std::size_t j = i + 1; j < d.size(); ++j) best = std::max(best, d[i].cross(d[j]).norm());
  return best;
}

// Plane through the centroid of {0, d_1..d_k} (CASSIE app, item 23); not
// yet tested for sharpness.
NodeFrame fit(const std::vector<Vec3>& d, const NodeFrameParams& params) {
  NodeFrame frame;
  const int k = static_cast<int>(d.size());
  if (k < 2) return frame;
  Vec3 c = Vec3::Zero();
  for (const Vec3& v : d) c += v;
  c /= static_cast<double>(k + 1);
  Mat3 m = c * c.transpose();  // the point P itself (0 - c)
  for (const Vec3& v : d) m += (v - c) * (v - c).transpose();
  Eigen::SelfAdjointEigenSolver<Mat3> eig(m);
  const Vec3 lambda = eig.eigenvalues();  // ascending
  // The points must span a plane: collinear directions leave the middle
  // eigenvalue at 0.
  if (!(lambda(1) > 1e-9 * (k + 1))) return frame;
  Vec3 n = eig.eigenvectors().col(0).normalized();
  int i = 0;
  n.cwiseAbs().maxCoeff(&i);  // deterministic sign: largest component positive
  if (n(i) < 0.0) n = -n;
  frame.normal = n;
  frame.defined = true;
  frame.fit_error = std::sqrt(std::max(lambda(0), 0.0) / (k + 1));
  return frame;
}

// Item 23: sharp when some tangent leaves the plane by more than θ
// (max |n·t| > sin θ), the tangents whichever set the plane was fitted to.
void test_sharp(NodeFrame& frame, const std::vector<Vec3>& tangents, const NodeFrameParams& params) {
  if (!frame.defined) return;
  for (const Vec3& t : tangents) frame.max_offset = std::max(frame.max_offset, std::abs(frame.normal.dot(t)));
  frame.sharp = frame.max_offset > std::cos(0.5 * std::numbers::pi - params.sharp_angle) ||
                frame.fit_error > params.sharp_error;
}

}  // namespace

NodeFrame fit_node_frame(const std::vector<Vec3>& tangents, const std::vector<Vec3>& opposite,
                         const NodeFrameParams& params) {
  const std::vector<Vec3> t = unit(tangents);
  NodeFrame f;
  if (largest_cross(t) >= params.collinear) {
    f = fit(t, params);
  } else {
    f = fit(unit(opposite), params);
    f.from_opposite = true;
  }
  test_sharp(f, t, params);
  return f;
}

}  // namespace sketchlab::soapfilm
