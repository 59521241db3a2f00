#pragma once
// Surfacer plugins keep patches up to date with the network.
#include <map>
#include <string>

#include "sketchlab/edit.hpp"
#include "sketchlab/event.hpp"
#include "sketchlab/sketch.hpp"

namespace sketchlab {

struct SurfaceUpdate {
  // Patch parts only (patches_added / patches_removed), ids from
  // sketch.network.next_patch_id() upwards.
  Edit edit;
  std::string error;  // non-empty on failure; the edit is then ignored
  // Optional figures by name (cycles searched, time per patch...).
  std::map<std::string, double> stats;
};

// The commands a surfacer answers (subset of the input events).
using SurfaceCommand = std::variant<AddPatchEvent, DeletePatchEvent>;

class Surfacer {
 public:
  virtual ~Surfacer() = default;
  // Called after `last` was applied to sketch.network.
  virtual SurfaceUpdate update(const Sketch& sketch, const Edit& last) = 0;
  virtual SurfaceUpdate command(const Sketch& sketch, const SurfaceCommand& command) = 0;
  // A global recompute from the whole sketch, asked for by a
  // RecomputeSurfaceEvent and once more at the end of a replay (run/stack.hpp).
  // Surfacers that keep up in update() need nothing here: the default is an
  // empty update.
  virtual SurfaceUpdate recompute(const Sketch& sketch) {
    (void)sketch;
    return {};
  }
};

}  // namespace sketchlab
