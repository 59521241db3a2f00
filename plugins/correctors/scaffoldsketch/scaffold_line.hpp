#pragma once
// Auto-correction of one scaffold stroke (ScaffoldSketch §3.2, §4.1): a line
// from the trigger's press to its release, corrected by IRLS against the
// existing scaffold; or, for a stroke shorter than the tick length, a tick
// keypoint on the scaffold line it crosses.
#include <vector>

#include "irls_solver.hpp"
#include "scaffold_params.hpp"
#include "sketchlab/plugin/corrector.hpp"

namespace sketchlab::scaffoldsketch {

// stats.outcomes["mode"]: what the stroke became.
inline constexpr const char* mode_scaffold_line = "scaffold_line";
inline constexpr const char* mode_tick = "tick";
inline constexpr const char* mode_shape_curve = "shape_curve";
inline constexpr const char* mode_shape_line = "shape_line";
inline constexpr const char* mode_shape_fallback = "shape_fallback";

// The new scaffold line from a to b (the press and release points, metres),
// drawn at zoom `scale`: candidates (eq. 1–5), IRLS (eq. 6–7), a line curve
// with start/end/midpoint keypoints, and a Node where a solved endpoint lies
// on existing curves. Constraints report every candidate with its final
// weight, residual (metres for point and length kinds, radians for angles)
// and whether IRLS kept it.
Correction correct_scaffold_line(const Vec3& a, const Vec3& b, StrokeId stroke,
                                 const Sketch& sketch, const ScaffoldParams& params,
                                 double scale);

// A tick (§3.2): the scaffold line nearest to the short stroke `points`
// within tick_length/s gets a keypoint of kind tick where it comes closest
// to the stroke (the edit replaces that curve with the same geometry and one
// more keypoint). No line there, or a keypoint already at that parameter:
// an empty edit, stats.extra["ignored"] = 1.
Correction correct_tick(const std::vector<Vec3>& points, StrokeId stroke, const Sketch& sketch,
                        const ScaffoldParams& params, double scale);

// The Constraint record of each term (kind, references, target, final IRLS
// weight, residual, enforced).
std::vector<Constraint> describe_terms(const std::vector<ScaffoldTerm>& terms,
                                       const IrlsResult& result, StrokeId stroke,
                                       const Workspace& workspace);

}  // namespace sketchlab::scaffoldsketch
