#pragma once
// Stroke–curve analysis (§4.2): end-classification (merge test eq. 1, join
// test eq. 2), topology rule, and type. Everything here is 2D: the stroke
// and the curve projected into the stroke's view, in pixels; d is the
// selection distance in pixels.
#include <optional>

#include "point_list.hpp"

namespace sketchlab::justdrawit {

// A curve as the analysis sees it: its projection (n x 2 pixels, in curve
// order) with cumulative arclength.
struct Projected {
  Points2 pts;
  std::vector<double> cum;
  bool closed = false;  // closed: pts.front() == pts.back()
  double length() const { return cum.empty() ? 0.0 : cum.back(); }
};
Projected make_projected(Points2 pts, bool closed);

// Signed curve-arclength step from `from` to `to`, the short way across the
// seam of a closed curve.
double curve_step(const Projected& c, double from, double to);

enum class EndKind { none, merge, join };

// How one end of the stroke meets the curve.
struct EndMatch {
  EndKind kind = EndKind::none;
  // +1 when walking the stroke forward (start -> end) moves towards
  // increasing curve arclength, -1 otherwise.
  int dir = 0;
  // Merge: s_s as stroke arclengths [s0, s1] (s0 < s1) and the curve
  // arclengths it projects to (at s0 and s1), average distance d_a (px) and
  // angle α_a (rad); overhang: walking on from the merge, the stroke runs off
  // the curve's end.
  double stroke_s0 = 0, stroke_s1 = 0, curve_at_s0 = 0, curve_at_s1 = 0;
  double d_a = 0, alpha_a = 0;
  bool overhang = false;
  // Join: stroke point p_s (stroke arclength) and curve end point p_c
  // (curve arclength, at one end); d_j (px), α_d, α_t, α_c (rad).
  double stroke_s = 0, curve_s = 0;
  bool at_curve_start = false;
  double d_j = 0, alpha_d = 0, alpha_t = 0, alpha_c = 0;
  // q_m of this end (§4.3: merge 0.7 d_a/d + 0.3 α_a/(3π/4); join eq. 3–5).
  double score = 0;
};

// The curve arclength halfway along a merge's overlap (curve_at_s0 to
// curve_at_s1): the start of a merge with a closed curve, where the stroke
// begins at the seam, runs from near the end across it (e.g. 570 → 40 px on
// a 600 px loop; the middle is 5, not 305).
double merge_middle(const Projected& c, const EndMatch& m);

// Merge test (eq. 1) of one stroke end (`at_end` false: the start).
std::optional<EndMatch> merge_test(const Points2& stroke, const std::vector<double>& cum,
                                   const Projected& curve, bool at_end, double d);
// Join test (eq. 2), best join searched up to 2d in from both ends.
std::optional<EndMatch> join_test(const Points2& stroke, const std::vector<double>& cum,
                                  const Projected& curve, bool at_end, double d);
// Merge if it passes, else join, else none.
EndMatch classify_end(const Points2& stroke, const std::vector<double>& cum,
                      const Projected& curve, bool at_end, double d);

enum class MatchType { oversketch, extend, partial_oversketch, extend_close };
const char* to_string(MatchType t);

struct CurveMatch {
  MatchType type = MatchType::extend;
  EndMatch start, end;  // start.kind/end.kind may be none (one-ended types)
  double q_m = 0;       // average over the ends that meet the curve
};

// Topology rule and type (§4.2) from the two end classifications; nothing
// when the stroke does not apply to this curve.
std::optional<CurveMatch> match_type(const EndMatch& start, const EndMatch& end,
                                     const Projected& curve, double d);

// Full analysis of a stroke (2D, pixels) against one projected curve.
std::optional<CurveMatch> analyze(const Points2& stroke, const Projected& curve, double d);

// §4.3 (1): the stroke closes on itself: its end merges with or joins its
// first third, and its start its last third. Returns the end's match against
// the first third, its score the mean of both ends' q_m.
std::optional<EndMatch> closes_on_itself(const Points2& stroke, double d);

// Join score q_m from eq. 3–5.
double join_score(double alpha_d, double alpha_t, double d_j, double d);

}  // namespace sketchlab::justdrawit
