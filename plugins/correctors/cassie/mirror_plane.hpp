#pragma once
// Whole-stroke projection onto the mirror plane (CASSIE app item 18,
// `MirrorPlane.Project`).
#include <vector>

#include "sketchlab/curve.hpp"
#include "sketchlab/workspace.hpp"

namespace sketchlab::cassie {

// Projects every control point of `curve` onto the workspace mirror plane
// and returns true when the stroke is that close to it: the largest control
// point distance (a poly-Bézier), or half the mean distance of the two ends
// (a line), under `max_distance`; every enforced intersection
// (`intersections`) within `on_plane` of the plane; and neither end tangent
// within `angle` of the normal. A projected stroke gets no mirrored copy.
bool project_onto_mirror(Curve& curve, const Workspace& workspace, const std::vector<Vec3>& intersections,
                         double max_distance, double on_plane, double angle);

}  // namespace sketchlab::cassie
