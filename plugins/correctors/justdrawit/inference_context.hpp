#pragma once
// What every step of one stroke's inference reads: the parameters, the
// stroke's camera, the selection distance d (pixels) and the visible draw
// plane, if any.
#include <optional>

#include "plane_depth.hpp"
#include "jdi_params.hpp"

namespace sketchlab::justdrawit {

struct Ctx {
  const JdiParams& p;
  const Camera& cam;
  double d;
  std::optional<Plane> draw_plane;  // visible draw plane
};

}  // namespace sketchlab::justdrawit
