#include "sketchlab/geometry/hausdorff.hpp"

#include <stdexcept>

#include "sketchlab/geometry/bezier.hpp"
#include "sketchlab/geometry/closest_point.hpp"

namespace sketchlab {

HausdorffDistance hausdorff_distance(const Curve& curve, const std::vector<Vec3>& polyline,
                                     int per_segment) {
  if (polyline.empty()) throw std::invalid_argument("hausdorff_distance: empty polyline");
  if (per_segment < 1) throw std::invalid_argument("hausdorff_distance: per_segment must be >= 1");
  HausdorffDistance h;
  for (int k = 0; k < curve.segment_count(); ++k)
    for (int i = 0; i <= per_segment; ++i) {
      const Vec3 q = evaluate(curve, k + static_cast<double>(i) / per_segment);
      h.curve_to_polyline = std::max(h.curve_to_polyline, closest_point_on_polyline(polyline, q).distance);
    }
  for (const Vec3& p : polyline)
    h.polyline_to_curve = std::max(h.polyline_to_curve, closest_point(curve, p).distance);
  return h;
}

}  // namespace sketchlab
