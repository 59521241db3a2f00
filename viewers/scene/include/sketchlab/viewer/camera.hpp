#pragma once
// A perspective camera, and the camera that frames a set of sketches. Every
// panel of a comparison uses the same camera, so differences between panels
// are differences between the sketches.
#include <string_view>
#include <vector>

#include "sketchlab/sketch.hpp"
#include "sketchlab/types.hpp"

namespace sketchlab::viewer {

struct Camera {
  Vec3 position{0.0, 0.0, 1.0};     // metres
  Vec3 focal_point{0.0, 0.0, 0.0};  // metres
  Vec3 view_up{0.0, 1.0, 0.0};      // unit, orthogonal to the view direction
  double view_angle_deg = 30.0;     // vertical field of view
};

// Where the camera looks from, relative to the workspace's up axis u and its
// front axis f (+Z projected orthogonal to u; -Y when u is ±Z): front looks
// along -f, side along -(u × f), top along -u (front at the bottom of the
// picture), iso from f + u×f + u.
enum class ViewDirection { iso, front, top, side };

std::string_view to_string(ViewDirection view);
// Throws std::invalid_argument naming the allowed values.
ViewDirection view_direction_from_string(std::string_view name);

// The camera looking from `view` at the centre of the sketches' union
// bounding box, at the smallest distance that keeps everything drawn (curves
// sampled at 1/200 of the box diagonal, nodes, patch meshes, 3D raw strokes)
// inside a viewport of width/height `aspect`, with `margin` (fraction of the
// half extent) around it. Up axis from the first
// sketch's workspace. Null pointers are skipped; an empty scene frames the
// unit cube at the origin. Throws std::invalid_argument for a non-positive
// or non-finite aspect.
Camera fit_camera(const std::vector<const Sketch*>& sketches, ViewDirection view,
                  double aspect = 1.0, double margin = 0.1, double view_angle_deg = 30.0);

// The union box fit_camera centres on (empty box when there is nothing to
// show): curves, nodes, patch meshes, raw strokes with 3D samples.
Box3 scene_bounds(const std::vector<const Sketch*>& sketches);

// The points fit_camera frames: curves sampled every `spacing` metres (> 0),
// nodes, patch mesh vertices, 3D raw stroke samples. Non-finite points and
// invalid curves are skipped.
std::vector<Vec3> scene_points(const std::vector<const Sketch*>& sketches, double spacing);

}  // namespace sketchlab::viewer
