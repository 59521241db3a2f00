#include "sketchlab/curve.hpp"

#include <cmath>
#include <string>

namespace sketchlab {

Curve make_line(const Vec3& a, const Vec3& b) {
  Curve c;
  c.kind = CurveKind::line;
  // Control points at 0, 1/3, 2/3, 1 make the cubic parameterisation linear in
  // arclength, so every curve algorithm treats the line exactly.
  c.control_points = {a, a + (b - a) / 3.0, a + 2.0 * (b - a) / 3.0, b};
  c.sharp = {false, false};
  return c;
}

std::string validate(const Curve& curve) {
  const std::size_t n = curve.control_points.size();
  if (n < 4 || (n - 1) % 3 != 0) {
    return "curve has " + std::to_string(n) + " control points; expected 3K+1 with K >= 1";
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (!curve.control_points[i].allFinite()) {
      return "curve control point " + std::to_string(i) + " is not finite";
    }
  }
  const std::size_t k = (n - 1) / 3;
  if (curve.sharp.size() != k + 1) {
    return "curve has " + std::to_string(curve.sharp.size()) + " sharp flags; expected " +
           std::to_string(k + 1) + " (one per joint, ends included)";
  }
  if (curve.closed && curve.control_points.front() != curve.control_points.back()) {
    return "curve is marked closed but its first and last control points differ";
  }
  return {};
}

void require_segments(const Curve& curve, const char* where) {
  if (curve.segment_count() < 1) {
    throw std::invalid_argument(std::string(where) + ": curve has " +
                                std::to_string(curve.control_points.size()) +
                                " control points; need 3K+1 with K >= 1");
  }
}

}  // namespace sketchlab
