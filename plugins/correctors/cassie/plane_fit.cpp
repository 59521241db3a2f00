#include "plane_fit.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace sketchlab::cassie {

PlaneFit fit_plane(const std::vector<Vec3>& points, double max_distance, double angle, bool test_snapped) {
  PlaneFit f;
  if (points.size() < 3) return f;
  for (const Vec3& p : points) f.centroid += p;
  f.centroid /= static_cast<double>(points.size());
  Mat3 cov = Mat3::Zero();
  for (const Vec3& p : points) cov += (p - f.centroid) * (p - f.centroid).transpose();
  Eigen::SelfAdjointEigenSolver<Mat3> es(cov);
  // A straight run of control points has no defined plane.
  if (!(es.eigenvalues()[1] > 1e-12 * std::max(es.eigenvalues()[2], 1e-300))) return f;
  f.normal = es.eigenvectors().col(0).normalized();
  if (!test_snapped) f.max_distance = plane_residual(points, f.normal);
  for (int a = 0; a < 3; ++a)
    if (std::abs(f.normal[a]) >= std::cos(angle)) {
      f.axis = a;
      f.normal = Vec3::Unit(a);
      break;
    }
  if (test_snapped) f.max_distance = plane_residual(points, f.normal);
  f.planar = f.max_distance <= max_distance;
  return f;
}

}  // namespace sketchlab::cassie
