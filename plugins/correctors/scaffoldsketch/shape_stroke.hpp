#pragma once
// Auto-correction of one shape stroke (ScaffoldSketch §4.2).
#include <vector>

#include "scaffold_params.hpp"
#include "sketchlab/plugin/corrector.hpp"
#include "sketchlab/preprocess/preprocess.hpp"

namespace sketchlab::scaffoldsketch {

// Arclength resampling of `points` every `spacing` metres (at least 2 points,
// both ends kept). Consecutive duplicates are ignored; an input without two
// distinct points gives its first point only (or nothing when empty).
std::vector<Vec3> resample_every(const std::vector<Vec3>& points, double spacing);

// The stroke (samples, metres; drawn at zoom `scale`) as a shape curve:
// resampled every sample_spacing/s, keypoints and tangents from the scaffold
// (§4.2.1); a PCA-straight stroke (§4.2.2) becomes the exact line between the
// first and last keypoints; otherwise the MVC piecewise Bézier (eq. 8–9).
// With fewer than 2 keypoints the kernel's freehand fit (`fallback`) is used
// (stats.outcomes["mode"] = mode_shape_fallback). Nodes join the curve to the
// scaffold lines at each keypoint. Constraints: a coincident_point per
// keypoint, a tangent per scaffold-snapped tangent, straight for lines.
Correction correct_shape_stroke(const Stroke& stroke, const Sketch& sketch,
                                const ShapeParams& params, double node_tolerance,
                                const PreprocessParams& fallback);

}  // namespace sketchlab::scaffoldsketch
