#include "plane_fit.hpp"

#include <Eigen/Eigenvalues>
#include <stdexcept>

namespace sketchlab::hermite_rbf {

PrincipalAxes principal_axes(const std::vector<Vec3>& points) {
  if (points.empty()) throw std::invalid_argument("principal_axes: no points");
  PrincipalAxes out;
  for (const Vec3& p : points) out.centroid += p;
  out.centroid /= static_cast<double>(points.size());
  Mat3 cov = Mat3::Zero();
  for (const Vec3& p : points) cov += (p - out.centroid) * (p - out.centroid).transpose();
  cov /= static_cast<double>(points.size());
  const Eigen::SelfAdjointEigenSolver<Mat3> eig(cov);  // ascending eigenvalues
  for (int i = 0; i < 3; ++i) {
    out.axes[i] = eig.eigenvectors().col(2 - i).normalized();
    out.spread[i] = std::max(0.0, eig.eigenvalues()(2 - i));
  }
  return out;
}

}  // namespace sketchlab::hermite_rbf
