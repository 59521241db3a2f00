#pragma once
// A 2D stroke as the inference sees it: pixel positions, the velocity-based
// uncertainty radius of every sample (§3.1 eq. 3) and polyline queries.
#include <vector>

#include "analytic_params.hpp"
#include "sketchlab/stroke.hpp"

namespace sketchlab::analytic {

struct Stroke2d {
  std::vector<Vec2> points;   // pixels, consecutive duplicates removed
  std::vector<double> delta;  // uncertainty radius per point, pixels
  double length = 0.0;        // pixels
  // At most ~100 points of the same polyline (every k-th point, ends kept)
  // for the many distance queries of eq. 7.
  std::vector<Vec2> coarse;
  std::vector<double> coarse_delta;
  bool hooks_cut = false;     // a hook was cut at an end (AnalyticParams::remove_hooks)
};

// δ_i = Lerp(v_i/v_max, δ_min, δ_max) in pixels (eq. 3), v_i in in/s from
// pixel speed / dpi. Speed at a point is the mean over its neighbouring
// intervals; an interval without positive duration counts as v_max (the
// widest radius: nothing is known about the hand's speed there).
Stroke2d make_stroke_2d(const Stroke& stroke, double dpi, const AnalyticParams& p);

// Distance (pixels) from q to the polyline, and the index of the nearest point
// of the polyline's nearest segment (for δ lookups).
struct PolylineHit {
  double distance = 0.0;
  int index = 0;
  double arclength = 0.0;  // pixels from the start
};
PolylineHit nearest_on_polyline(const std::vector<Vec2>& poly, const Vec2& q);

// Largest distance of the points from the chord first-last, pixels.
double chord_deviation(const std::vector<Vec2>& poly);

// Distance from q to the segment a-b.
double segment_distance(const Vec2& q, const Vec2& a, const Vec2& b);

}  // namespace sketchlab::analytic
