#pragma once
// Least-squares plane and line through points (PCA).
#include <vector>

#include "sketchlab/types.hpp"

namespace sketchlab::hermite_rbf {

struct PrincipalAxes {
  Vec3 centroid = Vec3::Zero();
  Vec3 axes[3];           // unit, by decreasing spread; axes[2] is the plane normal, axes[0] the line direction
  double spread[3] = {};  // eigenvalues of the covariance (m²), decreasing
};

// Needs at least one point (throws std::invalid_argument otherwise).
PrincipalAxes principal_axes(const std::vector<Vec3>& points);

}  // namespace sketchlab::hermite_rbf
