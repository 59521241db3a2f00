#pragma once
#include "sketchlab/types.hpp"

namespace sketchlab {

// One input sample. For VR input `position` is in workspace metres; for 2D
// input it is (x, y, 0) in pixels of the stroke's View (origin bottom-left,
// as OpenGL window coordinates).
struct Sample {
  Vec3 position = Vec3::Zero();
  double time = 0.0;      // seconds since the session started
  double pressure = 1.0;  // [0, 1]; devices without pressure report 1
  Quat orientation = Quat::Identity();  // controller/pen orientation

  bool operator==(const Sample& o) const {
    return position == o.position && time == o.time && pressure == o.pressure &&
           orientation.coeffs() == o.orientation.coeffs();
  }
};

}  // namespace sketchlab
