#pragma once
// Guidelines (§2.2) and dimension ticks (§2.3): strokes that are not geometry
// but construction aids. A vanishing guideline starts at a known point and
// runs to the vanishing point of an existing direction (or toward it, to the
// edge of the viewport, when it is off screen); image-parallel horizontal and
// vertical guidelines likewise run to the edge. A tick is a short stroke
// across a guideline.
#include <optional>
#include <vector>

#include "analytic_params.hpp"
#include "sketchlab/camera.hpp"
#include "scaffold.hpp"
#include "stroke_2d.hpp"

namespace sketchlab::analytic {

struct Guideline {
  Vec3 origin = Vec3::Zero();
  Vec3 direction = Vec3::UnitX();  // unit, pointing along the stroke
  bool image_parallel = false;
};

// The stroke's direction from the known point must be within
// guideline_angle of the direction's image, or its end within
// guideline_reach·δ (of that end) of the direction's image line.
// `forced`: the user drew in guide mode, so the end condition is dropped.
std::optional<Guideline> detect_guideline(const Scaffold& scaffold, const Camera& camera,
                                          const Stroke2d& stroke, const AnalyticParams& p,
                                          bool forced);

// Known points near a pixel: scaffold vertices and line intersections.
std::vector<Vec3> known_points_near(const Scaffold& scaffold, const Camera& camera, const Vec2& pixel,
                                    double radius);

struct TickTransfer {
  int guide = -1;  // scaffold line index receiving a tick
  Vec3 position = Vec3::Zero();
};

// §2.3: the tick's 3D point on the guideline it crosses (its projection
// meeting the tick's line within params.tick_reach·δ beyond the tick's ends;
// snapped to a nearby scaffold point), plus the distance A to every intersecting guideline
// transferred as ticks at ±A along it. Empty when the stroke is no tick.
std::vector<TickTransfer> detect_tick(const Scaffold& scaffold, const Camera& camera,
                                      const Stroke2d& stroke, const AnalyticParams& p);

}  // namespace sketchlab::analytic
