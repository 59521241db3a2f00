#pragma once
// Analytic-drawing construction (Schmidt et al. 2009, "Analytic Drawing of 3D
// Scaffolds" §2, Figures 1, 3, 6): how a designer trained in the method
// draws a model on paper or a tablet. A linear scaffold comes first — boxes
// started by one edge in the ground plane (Fig. 3a), every further edge traced
// along a guideline toward a vanishing point from a known point (Fig. 3b–d),
// so that corners fall on guideline intersections (Fig. 3e) — and the curves
// are sketched on the scaffold last (Fig. 1b), a circle inscribed in its
// square through the ends of the square's cross (the cube and the coffee mug
// of the paper's user study, §4).
#include <cstddef>
#include <optional>
#include <vector>

#include "ground_truth.hpp"
#include "planned_stroke.hpp"
#include "sketchlab/view.hpp"

namespace sketchlab::synthetic {

// The network plus the construction scaffold (Layer::scaffold lines) its
// curves need, derived from the geometry, not from the model's name:
//  - every circle (closed, four joints at the ends of two perpendicular equal
//    radii, as make_circle builds it) gets its circumscribed square, the
//    square's two diagonals (they cross at the centre) and its cross (the two
//    diameters through the joints, which end on the square's side midpoints);
//  - two circles on one axis (centres apart along their common normal) get
//    lines joining the corresponding corners of their squares (the cylinder's
//    or frustum's box);
//  - a line along no axis that does not join two circles gets the axis
//    path from its start to its end (its bounding box's edges: the slanted
//    line then connects two known points);
//  - when no axis-aligned horizontal line lies in the lowest plane of the
//    network, the footprint: the axis-aligned rectangle around the curve ends
//    in that plane (the chair's feet), so the first stroke can lie in the
//    ground plane.
// Lines already in the network (either orientation) are not repeated.
// Closed curves are then split into two open halves at joints 0 and n/2: the
// method infers a curve between two position constraints at the stroke's
// ends (§3.2), so a circle is sketched as two arcs between the ends of a
// diameter (the ellipse snap of §3.2 makes each a perfect elliptic arc).
// Axes are the unit x, y, z of the workspace (every built-in model is drawn
// axis-aligned, up +y).
GroundTruthNetwork with_construction_scaffold(const GroundTruthNetwork& net);

// The drawing order of §2: first the longest axis-aligned horizontal scaffold
// line in the lowest horizontal plane (the ground plane, Fig. 3a: it defines
// the primary vanishing directions — its own, its horizontal perpendicular
// and the vertical — so a diagonal will not do); then repeatedly the curve
// with an end on what is drawn, construction (scaffold) before the model's,
// most ends first, longest first (ties keep network order), reversed to
// start from the drawing when only its end is on it. A line along no axis
// waits until both its ends are drawn (it has no guideline to trace); a
// model's curve (not a line) until every construction line touching it is
// (a circle half: its square's sides and its cross). When
// nothing left touches the drawing, the curve whose start the fewest
// dimension ticks reach from it (with_guidelines draws them).
GroundTruthNetwork plan_analytic_drawing(const GroundTruthNetwork& net);

// The plan's curves in order, with guidelines and ticks (Fig. 3b–c, Fig. 6):
//  - after each line, from each of its ends, a guideline along every undrawn
//    axis-aligned line leaving that end, 1.25× that line's length, unless
//    that infinite line is drawn already (as a guideline or a line). A
//    guideline is drawn "from some known point to a vanishing point" (§2.2):
//    it runs along the sense of the axis that points away from the camera
//    (toward the vanishing point), whichever way the edge runs from the known
//    point. The far end of a later edge then lies on a guideline's line, and
//    on a guideline intersection when another one passes there;
//  - before a curve, its start — and its end, for a line along no axis or
//    one whose far end no drawn line or guideline across it marks — is made
//    a known point unless it is one or lies on a drawn line (Fig. 7d): by
//    dimension ticks (§2.3) along the fewest axis-aligned steps between the
//    network's points (curve ends, line crossings) from a known point, each
//    a guideline and a tick, or Figure 6's transfer where the step's length
//    is drawn along another axis already or its mirror image is a network
//    point (the tick on that axis's guideline, transferred to both sides);
//  - before a curve, for each of its ends inside a drawn line (not at its
//    ends): a guideline along that line from its end nearer the eye (so it
//    runs toward the vanishing point across the curve end), then a tick mark
//    (§2.3) there: a 24 px stroke across the guideline (perpendicular to it
//    and to the view ray), so the curve end becomes a known point.
// Ticks, like guidelines, have no `intended` curve. Every vanishing point
// of the tablet view is off screen, where the corrector takes a guideline
// drawn either way (§2.2). A guideline stroke is about 1.5 in long on
// screen at least (scaled at its start) (a direction drawn over a short stroke is only as good as the
// pen's error over its length). Detail zoom (§2's image-space pan/zoom): a
// curve whose projection spans less than 1.5 in is drawn, with the aids
// drawn for it, in `camera` zoomed in 4 times about its middle (same eye:
// the pen's pixels shrink in the scene); an aid that would leave that
// screen is drawn unzoomed. Both constants are choices (the paper gives
// none), 1.5 in being three times eq. 3's widest uncertainty radius.
std::vector<PlannedStroke> with_guidelines(const GroundTruthNetwork& plan, const View& camera);

}  // namespace sketchlab::synthetic
