#pragma once
// Back-and-forth scratch processing (§4.1): fold-over sections found with
// ShortStraw, then glued with the projection operator instead of a curve
// fit. Also used to blend a stroke with the previous stroke(s) it overlaps.
// All inputs are 2D point lists in pixels; d is the selection distance (px).
#include <optional>
#include <vector>

#include "point_list.hpp"

namespace sketchlab::justdrawit {

// Splits the stroke at ShortStraw corners and joins each piece that is not a
// fold-over (a section whose start does not lie within d of the previous
// section, running back over it) to its predecessor. One section: no fold.
std::vector<Points2> fold_over_sections(const Points2& stroke, double d);

// The averaging function of §4.1: p projected onto each section (skipping
// `exclude`); projections onto a section's interior are averaged with weights
// falling off with distance. Returns nothing when no section's interior is hit.
struct Average {
  Vec2 point;
  Vec2 tangent;  // unit, oriented like the sections
};
std::optional<Average> average_projection(const std::vector<Points2>& sections, const Vec2& p,
                                          double d, std::size_t exclude);

// Glues sections (any orientation) into one non-folding stroke: Hermite
// extensions (6 samples, tangents of length d), then three passes of the
// projection operator moving the middle 50 % by 0.25 and the ends by 0.75,
// then the points sorted along the longest section and down-sampled to d/10.
Points2 blend_sections(std::vector<Points2> sections, double d);

// The stroke unfolded: blend_sections(fold_over_sections) when it folds,
// else the stroke itself.
Points2 unfold_stroke(const Points2& stroke, double d);

// Fraction (by arclength) of `a` lying within d of `b` (§4.1: > 0.9 means
// "overlaps the last stroke").
double overlap_fraction(const Points2& a, const Points2& b, double d);

}  // namespace sketchlab::justdrawit
