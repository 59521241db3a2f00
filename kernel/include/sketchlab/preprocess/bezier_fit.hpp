#pragma once
// Least-squares G1 cubic poly-Bézier fitting after Schneider, "An algorithm
// for automatically fitting digitized curves" (Graphics Gems, 1990), as used
// by CASSIE (thesis §3.2.2 "Bezier curve fitting").
//
// The input is first cut into G1 sections at corners (tangent turn above
// max_g1_angle, CASSIE's π/4 maximum angular variation inside a G1 section).
// Each section is fitted independently: chord-length parameterisation, fixed
// unit end tangents, least squares for the two inner control points, Newton
// reparameterisation when the error is moderate, and otherwise a split at the
// point of maximum error with a shared tangent (so interior joints are G1).
#include <cstddef>
#include <numbers>
#include <vector>

#include "sketchlab/curve.hpp"

namespace sketchlab {

struct BezierFitParams {
  // Maximum distance of any input point to the fitted curve (units of the
  // points; CASSIE: 0.5δ). Must be > 0.
  double tolerance = 0.01;
  // Tangent turn (radians) above which a joint is sharp. In (0, π].
  double max_g1_angle = std::numbers::pi / 4;
  // Scale (units) at which turns and tangents are measured: turn at p_i is
  // the angle between the chords to the nearest points at distance >=
  // corner_window on each side; tangents use chords of tangent_window.
  // Both > 0 (pipeline: δ and δ/2).
  double corner_window = 0.02;
  double tangent_window = 0.01;
  // Newton reparameterisation rounds per segment before splitting, tried
  // when the error is under reparameterize_below × tolerance (Schneider: 4).
  int max_reparameterizations = 8;
  double reparameterize_below = 4.0;
  // Tolerance of the pieces of a split (> 0), or 0 for `tolerance`. The
  // CASSIE app passes a fixed 0.01 to its recursive calls whatever the zoom
  // (reference item 4: an original quirk).
  double split_tolerance = 0.0;
};

// Indices of corners of the polyline (strictly inside, increasing): local
// maxima of the turn above max_g1_angle, with at least corner_window / 2 of
// the stroke on either side.
std::vector<std::size_t> find_corners(const std::vector<Vec3>& points,
                                      const BezierFitParams& params);

// Corners as the CASSIE app finds them on the raw samples (reference item 4,
// `GetG1sections`): the largest turn (sample_turns across the sample; the
// consecutive reading finds fewer corners and agrees less with CASSIE's
// curves, cassie README) of each run of samples
// turning by more than `angle`, kept when the sections on both sides (from
// the previous corner, to the end) have at least `min_samples` samples and
// are longer than `min_length`. Indices strictly inside, increasing.
std::vector<std::size_t> find_corners_by_turns(const std::vector<Vec3>& points, double angle,
                                               std::size_t min_samples, double min_length);

// Fits each section on its own (chord-length Schneider fit, G1 inside) and
// joins them; consecutive sections share their end point, and the joints
// between sections are sharp. Same output and errors as fit_poly_bezier,
// without corner detection (params.max_g1_angle, corner_window unused).
Curve fit_poly_bezier_sections(const std::vector<std::vector<Vec3>>& sections,
                               const BezierFitParams& params);

// Fits a G1 poly-Bézier to points (n >= 2 distinct points; consecutive
// duplicates are ignored). Every input point lies within `tolerance` of the
// result. Output: kind bezier, 3K+1 control points, K+1 sharp flags (true at
// the corners found by find_corners, false at the ends and at G1 joints).
// Throws std::invalid_argument for fewer than 2 distinct points, non-finite
// points or parameters out of range.
Curve fit_poly_bezier(const std::vector<Vec3>& points, const BezierFitParams& params);

}  // namespace sketchlab
