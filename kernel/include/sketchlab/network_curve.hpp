#pragma once
// The network curve a corrector (or the lab, or a tool) adds for a new curve:
// one constructor, so that every new curve gets the same keypoints and the
// same layer rule.
#include "sketchlab/network_types.hpp"

namespace sketchlab {

// The layer of the curve a stroke on `stroke_layer` makes: the stroke's own,
// except that automatic strokes make free curves.
Layer curve_layer(Layer stroke_layer);

// A network curve for `curve`: the given id, layer and source stroke (0:
// none), default_keypoints(curve) (start, end, arclength midpoint) and no
// normals. The id is the caller's to choose (Network::next_curve_id() for
// the first curve of an edit). Throws std::invalid_argument naming the
// problem when `curve` is not valid (validate(), curve.hpp).
NetworkCurve make_network_curve(CurveId id, Curve curve, Layer layer, StrokeId source_stroke = 0);

}  // namespace sketchlab
