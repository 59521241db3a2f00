#pragma once
// Straight-line detection for strokes.
//
// CASSIE (thesis §3.2.2 "Line fitting") replaces a stroke by a line when
// (1) its length L_c is close to the distance between its endpoints L_l, as
// in ShipShape, and (2) its average drawing speed is above a threshold, so
// that drawing slowly keeps a deliberate quasi-straight curve. The thesis
// gives no numbers; we choose:
//  - L_l / L_c >= 0.98. A circular arc reaches 0.98 at about 40° of turn and
//    a symmetric bow at a sagitta of about 8.7 % of its length, close to
//    ScaffoldSketch's 8 % deviation limit below.
//  - mean speed >= 0.2 m/s of hand motion (a deliberate slow stroke is
//    slower; a quick construction line is 0.3–1 m/s). In workspace units at
//    zoom s this is 0.2/s m/s, like every distance threshold δ/s.
// L_c is measured on the polyline through the stroke ends and the centroids
// of consecutive pieces of about `resample_spacing` arclength (δ/s in the
// pipeline): raw 90 Hz samples carry millimetre jitter that would inflate
// the polyline length of even a perfectly straight stroke.
//
// ScaffoldSketch (§4.2.2, shape curves) instead fits a PCA line and accepts
// it when every sample lies within 8 % of the PCA segment's length and that
// length is within 10 % of the stroke's arclength: `fit_pca_line`.
#include <vector>

#include "sketchlab/types.hpp"

namespace sketchlab {

struct LineDetectionParams {
  double min_length_ratio = 0.98;  // chord / length, in (0, 1]
  double min_speed = 0.2;          // units per second (m/s); 0 disables
  double resample_spacing = 0.02;  // units (m); must be > 0
};

struct LineDetection {
  bool is_line = false;
  double length_ratio = 0.0;  // chord / coarse polyline length, in [0, 1]
  double mean_speed = 0.0;    // coarse length / duration; +inf if no timing
  double length = 0.0;        // coarse polyline length (L_c)
};

// CASSIE criterion on points (n >= 2, not all equal) with times (seconds,
// same size and non-decreasing, or empty when the input has no timing; then
// or when the duration is 0 the speed test is skipped). Throws
// std::invalid_argument for bad sizes, non-finite values, decreasing times,
// zero-length strokes or parameters out of range.
LineDetection detect_line(const std::vector<Vec3>& points, const std::vector<double>& times,
                          const LineDetectionParams& params);

// The CASSIE app's line test (reference item 2, `Beautifier.Beautify`), on
// the raw (filtered) samples: with L the polyline length and c the chord, a
// line when L < min_length, or when (L − c)/c < max_excess and the mean
// speed L / duration exceeds min_speed (skipped without times or with zero
// duration). The app compares the excess ratio with δ(s) itself, so the
// caller passes max_excess = δ/s (a number), min_length = δ/s and
// min_speed = (δ/s)/0.05 s. Points and times as for detect_line; the
// returned length is L (not the coarse polyline).
LineDetection detect_line_by_excess(const std::vector<Vec3>& points,
                                    const std::vector<double>& times, double max_excess,
                                    double min_speed, double min_length);

struct PcaLine {
  bool is_line = false;
  Vec3 a = Vec3::Zero();  // segment of the principal axis spanning the
  Vec3 b = Vec3::Zero();  // projections of all points, oriented first->last
  double max_deviation = 0.0;  // largest distance of a point to the axis
};

// ScaffoldSketch criterion: is_line when max_deviation <= max_deviation_ratio
// * |b - a| and |b - a| >= (1 - length_tolerance) * polyline length. Points
// as for detect_line.
PcaLine fit_pca_line(const std::vector<Vec3>& points, double max_deviation_ratio = 0.08,
                     double length_tolerance = 0.10);

}  // namespace sketchlab
