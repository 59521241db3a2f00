#pragma once
// The state plugins read: the workspace, the network (with patches), every
// raw stroke by id, and the undo history. Folding a recording's events
// through a plugin stack produces it (see session.hpp).
#include <map>
#include <vector>

#include "sketchlab/history.hpp"
#include "sketchlab/network.hpp"
#include "sketchlab/stroke.hpp"
#include "sketchlab/workspace.hpp"

namespace sketchlab {

struct Sketch {
  Workspace workspace;
  Network network;
  std::map<StrokeId, Stroke> strokes;  // every stroke received, even undone ones
  History history;
  bool correction_enabled = true;
  Layer mode = Layer::automatic;  // current drawing mode (strokes may override)
  bool operator==(const Sketch&) const = default;
};

// Ids of the curves in the network that came from `stroke`, ascending.
std::vector<CurveId> curves_of_stroke(const Sketch& sketch, StrokeId stroke);

// Strokes whose edits are currently applied (history order, oldest first).
std::vector<StrokeId> live_strokes(const Sketch& sketch);

// Live strokes that still have curves in the network (a stroke whose curves
// were deleted drops out), in the same order.
std::vector<StrokeId> strokes_with_curves(const Sketch& sketch);

}  // namespace sketchlab
