#include "sketchlab/network_types.hpp"

#include <stdexcept>
#include <string>

#include "sketchlab/geometry/arclength.hpp"
#include "sketchlab/geometry/bezier.hpp"

namespace sketchlab {

std::vector<Keypoint> default_keypoints(const Curve& curve) {
  if (const std::string why = validate(curve); !why.empty())
    throw std::invalid_argument("default_keypoints: " + why);
  const double t_max = curve.t_max();
  const double t_mid = parameter_at_arclength(curve, 0.5 * arclength(curve));
  return {
      Keypoint{Keypoint::Kind::start, 0.0, evaluate(curve, 0.0)},
      Keypoint{Keypoint::Kind::end, t_max, evaluate(curve, t_max)},
      Keypoint{Keypoint::Kind::midpoint, t_mid, evaluate(curve, t_mid)},
  };
}

}  // namespace sketchlab
