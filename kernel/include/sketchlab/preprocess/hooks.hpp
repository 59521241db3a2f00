#pragma once
// Hook removal (CASSIE thesis §3.2.2 "Hooks removal", after Liu et al.): VR
// strokes often start and end with a short involuntary flick made while the
// trigger is pressed or released. A hook shows as a C1 discontinuity (a sharp
// turn) close to an end of the stroke; everything before it is cut.
#include <cstddef>
#include <limits>
#include <numbers>
#include <vector>

#include "sketchlab/preprocess/turns.hpp"
#include "sketchlab/types.hpp"

namespace sketchlab {

// Inclusive range [first, last] of point indices kept from an input.
struct IndexRange {
  std::size_t first = 0;
  std::size_t last = 0;
  std::size_t size() const { return last - first + 1; }
  bool operator==(const IndexRange&) const = default;
};

// Distances are in the units of the points (metres for VR strokes; the
// pipeline passes δ/s-scaled values).
struct HookParams {
  // A hook spans at most this Euclidean distance from its stroke end (3δ).
  double max_length = 0.06;
  // ... and at most this fraction of the stroke's polyline length (15 %).
  double max_fraction = 0.15;
  // Turns closer than this to the end are ignored: too small to matter and
  // dominated by sampling noise (δ/2).
  double min_length = 0.01;
  // Minimum turn (radians, in (0, π)) that counts as a C1 discontinuity.
  double min_angle = std::numbers::pi / 4;
  // Optional straightness of the hook itself: the turn between the fitted
  // directions of its outer and inner halves (split where it reaches a/2
  // from the end) must be at most this fraction of the turn at the cut. A
  // flick is straight; a tight smooth bend of the drawn curve (the end of a
  // flat ellipse's projection) bends within the piece too. Only hooks whose
  // halves are at least min_length long are tested (shorter ones are
  // jitter-sized: their halves have no measurable direction). Infinity (the
  // default, CASSIE's rule) disables the test.
  double max_bend_ratio = std::numeric_limits<double>::infinity();
};

// Range of `points` (n >= 2) left after cutting a hook at each end.
//
// A candidate cut i near the start lies at distance a = |p_i - p_0| in
// [min_length, max_length] with cumulative length <= max_fraction of the
// stroke. Its turn is the angle between the least-squares directions of the
// hook p_0..p_i and of the points from p_i to the first later point at
// distance >= a; the turn must also reach min_angle at half that scale (a/2
// on both sides), so only turns concentrated at p_i (a corner, not a smooth
// bend) qualify. The candidate with the largest turn >= min_angle is cut
// (p_i is kept); with a finite max_bend_ratio, candidates whose hook bends
// more than that (see HookParams) are skipped. The end is handled
// symmetrically on what remains. Returns {0, n-1} when there is no hook.
// Throws std::invalid_argument for n < 2, non-finite points or parameters
// out of range (max_bend_ratio must be >= 0).
IndexRange find_hookless_range(const std::vector<Vec3>& points, const HookParams& params);

// The CASSIE app's rule (reference item 3, `InputStroke.GetG1sections`):
// from each end, scan the samples while the scanned polyline length is under
// min(max_length, max_fraction of the stroke's length) and cut at the last
// sample whose turn (sample_turns with `span`) exceeds min_angle, only if
// more than min_remaining − 1 samples remain; there is no minimum hook
// length. The end is scanned on what the start cut left.
struct TurnHookParams {
  double max_length = 0.06;        // 3δ (units of the points)
  double max_fraction = 0.15;
  double min_angle = std::numbers::pi / 6;
  std::size_t min_remaining = 5;   // "more than 4 samples remain"
  // "where the averaged direction turns": from one sample to the next (the
  // default, which agrees better with CASSIE's curves on its exported
  // sessions; plugins/correctors/cassie/README.md) or across the sample.
  TurnSpan span = TurnSpan::consecutive;
};

// Same contract as find_hookless_range (n >= 2, finite points); throws
// std::invalid_argument for parameters out of range (max_length <= 0,
// max_fraction outside [0, 0.5), min_angle outside (0, π)).
IndexRange find_hookless_range_by_turns(const std::vector<Vec3>& points,
                                        const TurnHookParams& params);

}  // namespace sketchlab
