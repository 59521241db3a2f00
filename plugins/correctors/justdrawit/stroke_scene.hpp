#pragma once
// The scene one stroke is analysed against (§4.5): the network's curves
// sampled in 3D and projected into the stroke's view, with their eye depths,
// after bounding-box culling. Also the stroke's own pixels.
#include <vector>

#include "sketchlab/camera.hpp"
#include "point_list.hpp"
#include "sketchlab/network.hpp"
#include "sketchlab/stroke.hpp"
#include "stroke_curve_analysis.hpp"

namespace sketchlab::justdrawit {

struct SceneItem {
  CurveId id = 0;
  Points3 pts3;
  Projected proj;
  Vec3 centroid = Vec3::Zero();
  double z_min = 0, z_max = 0;
};

struct Scene {
  std::vector<SceneItem> items;  // curves not culled, ascending id
  double Z_min = 0, Z_max = 0;   // eye depth range of the whole network
};

// Whether a pixel can come from a pen or mouse on the stroke's screen: at most
// one viewport width (height) left or right (below or above) of the viewport.
// Samples farther out are tracking glitches (a 65535 px spike; issue 17, D6)
// and are left out of the analysis: resampled at 0.1 d, a single one would
// otherwise add 10^5 points.
bool on_screen(const Vec2& pixel, const Vec4& viewport);

// The stroke's on_screen sample positions as pixels (x, y).
Points2 pixels(const Stroke& stroke);

// The analysis resamples strokes at 0.1 d (§4.5), but never into more than
// this many points: several of its passes grow with the square of the count.
inline constexpr double max_stroke_points = 20000;
// The resampling step for the stroke pixels `pts`: 0.1 d, or longer to stay
// within max_stroke_points.
double stroke_spacing(const Points2& pts, double d);

// The curves of `net` seen by `cam`, sampled at 0.1 d in pixels; with `cull`,
// those far outside the stroke's box are left out (§4.5, margin 8d).
Scene build_scene(const Network& net, const Camera& cam, const Points2& stroke, double d, bool cull);

// The same curve walked from its other end.
SceneItem reversed_item(SceneItem it);

}  // namespace sketchlab::justdrawit
