#pragma once
// This plugin's surfacer with its cost measured: each update/command is timed
// (wall and CPU time of the calling thread, which a shared machine's load
// does not inflate) and the meshing stages of every patch are kept. Used by
// the CASSIE replay (cassie_replay.hpp) and the end-to-end benchmark, so both
// report the surfacer's share the same way. Not thread-safe.
#include <vector>

#include "soapfilm_surfacer.hpp"

namespace sketchlab::soapfilm {

// CPU time of the calling thread (ms).
double thread_cpu_ms();

// What the surfacer cost since the last take().
struct SurfacerCost {
  double wall_ms = 0.0, cpu_ms = 0.0;    // update() + command() calls
  std::vector<PatchMeshTimings> meshed;  // per patch meshed, in order
};

class TimedSoapfilm : public Surfacer {
 public:
  explicit TimedSoapfilm(const SoapfilmParams& params) : params_(params) {}
  SurfaceUpdate update(const Sketch& sketch, const Edit& last) override;
  SurfaceUpdate command(const Sketch& sketch, const SurfaceCommand& command) override;
  // Returns the cost accumulated since the previous call and resets it.
  SurfacerCost take();

 private:
  SoapfilmParams params_;
  SurfacerCost cost_;
};

}  // namespace sketchlab::soapfilm
