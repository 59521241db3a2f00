#pragma once
// The JustDrawIt stroke inference engine (Grimm & Joshi 2012, §4–6) as a
// function: (2D stroke, sketch) -> correction. Reads earlier strokes and the
// undo history from the sketch (blending with the previous strokes, last
// edited curve), never mutates it.
#include "jdi_params.hpp"
#include "point_list.hpp"
#include "sketchlab/plugin/corrector.hpp"

namespace sketchlab::justdrawit {

// The stroke as the analysis uses it (§4.1, §4.5): on-screen pixels,
// resampled to 10 points per d, N rounds of smoothing, unfolded when it
// scratches back and forth (if enabled).
Points2 prepare_stroke(const Stroke& stroke, const JdiParams& p);

Correction justdrawit_correct(const Stroke& stroke, const Sketch& sketch, const JdiParams& p);

}  // namespace sketchlab::justdrawit
