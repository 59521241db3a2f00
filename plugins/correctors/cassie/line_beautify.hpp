#pragma once
// Straight lines (CASSIE app item 17, `LineCurve.Constrain/ConstrainTo`;
// thesis Appendix A): the line's ends are moved onto at most two raw
// constraints (no correction, no overlap cut), then possibly onto an axis.
#include <vector>

#include "constraint_types.hpp"

namespace sketchlab::cassie {

struct LineResult {
  Vec3 a = Vec3::Zero(), b = Vec3::Zero();
  std::vector<int> used;      // constraint indices the line was fitted to (0, 1 or 2)
  std::vector<int> enforced;  // those the final line passes within `keep` of (they get a node)
  int axis = -1;              // axis the direction was snapped to, or -1
};

// a, b: the detected line's ends; `constraints` in detection order. With
// more than two, the first detected and the one farthest from it are used;
// of two closer than `keep` one is kept (an intersection preferred). Each is
// matched to the end it is nearer along the line, except that one within
// `snap` of an end is that end's (of two near the same end, the first
// detected, and the other end gets none); an end snaps to its
// constraint when within `snap` of it or when the constraint lies beyond
// it; otherwise end a is projected onto the line from its constraint to b,
// then b onto the line from the new a to its constraint, except that a lone
// constraint snapping neither end moves the whole line across onto it,
// direction kept (CASSIE's own lines; line_beautify.cpp). With at most one
// constraint and `axis_snap`, a direction within `angle` of an axis (the
// first such) is rotated onto it, about a (no constraint) or the
// constrained point, when the other end moves less than `snap`.
LineResult beautify_line(const Vec3& a, const Vec3& b, const std::vector<Candidate>& constraints,
                         double snap, double keep, double angle, bool axis_snap);

}  // namespace sketchlab::cassie
