#pragma once
// Straight lines (thesis Appendix A; CHI supplemental): at most two
// intersections, the ones nearest to each end; an endpoint within 2δ of its
// constraint snaps to it, otherwise the line is projected onto (two) or
// translated through (one) the constraints; a free direction within θ of an
// axis is aligned to it.
#include <vector>

#include "candidates.hpp"

namespace sketchlab::cassie {

struct LineResult {
  Vec3 a = Vec3::Zero(), b = Vec3::Zero();
  std::vector<int> enforced;  // candidate indices
  int axis = -1;              // axis the direction was aligned to, or -1
};

// a, b: the detected line's ends; candidates detected on make_line(a, b)
// (t_stroke in [0, 1]; closure ignored); snap = 2δ(s).
LineResult beautify_line(const Vec3& a, const Vec3& b, const std::vector<Candidate>& candidates,
                         double snap, double angle, bool axis_snap);

}  // namespace sketchlab::cassie
