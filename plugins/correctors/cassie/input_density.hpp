#pragma once
// Dense input for the CASSIE app's turn rules. The app measures hooks and
// corners (items 3–4) as direction turns between consecutive samples of its
// 90 Hz stream, filtered at 0.1δ (item 1). The exported CASSIE sessions keep
// those samples thinned by RDP at 2 mm (data/cassie/README.md), so a turn
// that the app saw spread over many small steps lands on one sample and reads
// as a hook or a corner. Inserting points on the thinned polyline restores a
// sample spacing like the app's; RDP at 0.1δ (item 4) removes them again
// before fitting, so only the turn rules and the time trims see them.
#include "sketchlab/stroke.hpp"

namespace sketchlab::cassie {

// The stroke with points inserted, equally spaced, in every gap between
// consecutive samples longer than `max_gap` (m, > 0), so that no gap exceeds
// it; positions and times are interpolated linearly, orientations by slerp,
// pressures linearly. Samples already there are kept unchanged.
// max_gap <= 0 returns the stroke unchanged.
Stroke densify_stroke(const Stroke& stroke, double max_gap);

}  // namespace sketchlab::cassie
