#pragma once
// The edit one stroke makes (§4.4, §6): the built points as a network curve
// (new, or replacing the edited one; the second of a combination removed),
// the nodes on the edited curves moved onto it or released, their patches
// dropped, default normals, and the constraints that were considered.
#include <string>
#include <vector>

#include "apply_decision.hpp"
#include "inference_context.hpp"
#include "sketchlab/plugin/corrector.hpp"
#include "stroke_scene.hpp"

namespace sketchlab::justdrawit {

struct Outcome {
  Edit edit;
  std::vector<Constraint> constraints;
  CorrectionStats stats;
  std::string error;
};

// Adds the edit, the constraints and the "surface" statistic to `o`.
// `item_a` is the curve edited (null for a new curve), `item_b` the second
// curve of a combination; `surface_used` the drawing surface of a new curve.
void add_edit(Outcome& o, const Built& built, Decision decision, const SceneItem* item_a,
              const SceneItem* item_b, const std::string& surface_used, const Stroke& stroke,
              const Network& net, const Ctx& ctx);

}  // namespace sketchlab::justdrawit
