#pragma once
// Applying the chosen decision (§4.4): the stroke promoted to 3D against the
// curve(s) it edits (depths anchored where it overlaps them, extrapolated
// past) and joined into them with Hermite splices, then smoothed; or a new
// curve closed on itself. Yields points only: curve_edit.hpp makes the edit.
#include <string>
#include <vector>

#include "choice.hpp"
#include "inference_context.hpp"
#include "point_list.hpp"
#include "stroke_scene.hpp"

namespace sketchlab::justdrawit {

struct Built {
  Points3 pts;
  bool closed = false;
  std::vector<double> objectives;  // one per join
  std::string error;
};

// Over-sketch, extend, extend-and-close or partial over-sketch of one curve
// (`item`, as the candidate matched it). Sets `error` when the curve or the
// stroke cannot be given depths in this view.
Built apply_single(const Candidate& cand, SceneItem item, const Points2& s2, const Ctx& ctx);

// Combination (§4.3 (2)): the stroke leaves `a`'s end and enters `b`'s start.
Built apply_combine(const Candidate& cand, SceneItem a, SceneItem b, const Points2& s2, const Ctx& ctx);

// A new curve (already placed in `built`) that closes on itself: the end is
// spliced into the start where `c.self` matched. `cum` is the stroke's
// cumulative arclength in pixels.
void close_new_curve(Built& built, const Candidate& c, const std::vector<double>& cum, const Ctx& ctx);

}  // namespace sketchlab::justdrawit
