#pragma once
// The surfacer itself as free functions over (sketch, edit|command), so tests
// and tools use exactly what the plugin does.
#include "sketchlab/plugin/surfacer.hpp"
#include "soapfilm_params.hpp"

namespace sketchlab::soapfilm {

// Patch edit after `last` was applied (Appendix B upkeep + meshing).
// `per_patch`, when given, receives the meshing stages' CPU times of each
// cycle meshed (appended, in discovery order).
SurfaceUpdate soapfilm_update(const Sketch& sketch, const Edit& last, const SoapfilmParams& params,
                              std::vector<PatchMeshTimings>* per_patch = nullptr);
// Add a patch at a point (manual) or delete the patch nearest a point.
SurfaceUpdate soapfilm_command(const Sketch& sketch, const SurfaceCommand& command,
                               const SoapfilmParams& params);

// A patch (id, boundary, mesh) for a cycle; nullopt if meshing fails.
// `timings`, when given, receives the meshing stages' CPU times.
std::optional<Patch> make_patch(const Network& network, PatchId id,
                                const std::vector<OrientedSegment>& boundary, bool automatic,
                                const SoapfilmParams& params, PatchMeshTimings* timings = nullptr);

}  // namespace sketchlab::soapfilm
