#pragma once
// A curve is a cubic poly-Bézier: K segments share end control points, so it
// has 3K+1 control points. Segment k uses points [3k, 3k+3]. The global
// parameter t runs over [0, K]; t in [k, k+1] is segment k at local t-k.
#include <string>
#include <vector>

#include "sketchlab/types.hpp"

namespace sketchlab {

enum class CurveKind {
  bezier,  // a G1/G0 cubic poly-Bézier
  line,    // a straight segment; stored as one cubic with control points at
           // 0, 1/3, 2/3, 1 of the segment so every curve algorithm applies
};

struct Curve {
  CurveKind kind = CurveKind::bezier;
  std::vector<Vec3> control_points;  // 3K+1 points
  // One flag per joint (K+1 entries: both ends included). A sharp joint is a
  // tangent discontinuity the fit kept on purpose (turn above 45°).
  std::vector<bool> sharp;
  // Closed curves have control_points.front() == control_points.back().
  bool closed = false;

  int segment_count() const {
    return control_points.size() < 4 ? 0 : static_cast<int>((control_points.size() - 1) / 3);
  }
  double t_max() const { return static_cast<double>(segment_count()); }

  bool operator==(const Curve&) const = default;
};

// A straight curve from a to b (kind = line).
Curve make_line(const Vec3& a, const Vec3& b);

// Throws std::invalid_argument "<where>: curve has N control points; need
// 3K+1 with K >= 1" unless the curve has at least one segment: the
// precondition of every geometry function.
void require_segments(const Curve& curve, const char* where);

// Empty when the curve is well formed (3K+1 points with K >= 1, finite
// coordinates, K+1 sharp flags, closed curves closed), else the reason.
std::string validate(const Curve& curve);

}  // namespace sketchlab
