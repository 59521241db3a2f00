#pragma once
// One stroke a synthetic person will draw: the 3D curve traced, its layer,
// the intended curve it draws (index into the planned network; none for
// construction aids such as guidelines and ticks) and the camera it is drawn
// in (0: the tablet view, 1: the second view), and the draw plane the person
// placed for it (none: the view plane through the model).
#include <cstddef>
#include <optional>

#include "sketchlab/curve.hpp"
#include "sketchlab/stroke.hpp"
#include "sketchlab/view.hpp"

namespace sketchlab::synthetic {

struct PlannedStroke {
  Curve curve;
  Layer layer = Layer::scaffold;
  std::optional<std::size_t> intended;
  int view = 0;
  std::optional<Vec4> draw_plane;  // (n, d) with n·x = d, |n| = 1
  std::optional<View> zoomed;      // drawn in this view instead (same eye, image zoom)
};

}  // namespace sketchlab::synthetic
