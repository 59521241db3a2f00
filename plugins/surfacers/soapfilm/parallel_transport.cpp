#include "parallel_transport.hpp"

#include <cmath>

#include "curve_tangent.hpp"

namespace sketchlab::soapfilm {

Vec3 parallel_transport(const Curve& curve, const std::vector<double>& parameters, bool forward,
                        const Vec3& v) {
  if (parameters.size() < 2) return v;
  Vec3 out = v;
  const bool increasing = forward;
  Vec3 prev = one_sided_tangent(curve, parameters.front(), increasing);
  for (std::size_t i = 1; i < parameters.size(); ++i) {
    // Inside the path use the tangent of the piece being travelled.
    const Vec3 next = one_sided_tangent(curve, parameters[i], !increasing);
    const Vec3 axis = prev.cross(next);
    const double s = axis.norm(), c = prev.dot(next);
    if (s > 1e-12) out = Eigen::AngleAxisd(std::atan2(s, c), axis / s) * out;
    // At a joint the tangent may jump: continue from the outgoing one.
    prev = one_sided_tangent(curve, parameters[i], increasing);
    if (prev.cross(next).norm() > 1e-12) {
      const Vec3 a2 = next.cross(prev);
      const double s2 = a2.norm();
      out = Eigen::AngleAxisd(std::atan2(s2, next.dot(prev)), a2 / s2) * out;
    }
  }
  return out;
}

}  // namespace sketchlab::soapfilm
