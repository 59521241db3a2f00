// JustDrawIt's implicit surfacing (Grimm & Joshi 2012, §6; Hermite RBF of
// Macêdo, Gois & Velho) as a surfacer plugin. The surface is global: it is
// rebuilt on request (recompute_surface / add_patch events) and at the end of
// a replay, not after every stroke.
#include "hermite_rbf_surfacer.hpp"
#include "sketchlab/plugin/plugin_api.hpp"

namespace {

using namespace sketchlab;

class HermiteRbfSurfacer : public Surfacer {
 public:
  explicit HermiteRbfSurfacer(const Params& p) : params_(hermite_rbf::hermite_rbf_params(p)) {}
  SurfaceUpdate update(const Sketch&, const Edit&) override { return {}; }
  SurfaceUpdate command(const Sketch& sketch, const SurfaceCommand& command) override {
    return hermite_rbf::surface_command(sketch, command, params_, &state_);
  }
  SurfaceUpdate recompute(const Sketch& sketch) override {
    return hermite_rbf::recompute_surface(sketch, params_, &state_);
  }

 private:
  hermite_rbf::HermiteRbfParams params_;
  hermite_rbf::SurfaceState state_;  // the previous surface's model: the next recompute updates what changed
};

PluginDescriptor describe() {
  return surfacer_descriptor<HermiteRbfSurfacer>(
      "hermite_rbf", "1.0",
      "JustDrawIt §6 implicit surface: Hermite RBF (r³ + linear) through point, tangent and normal "
      "constraints of the curves, as a partition of unity of local fits (or one dense solve), meshed by "
      "flying edges (VTK) and trimmed where no curves enclose it; recomputed on request and at the end of a replay",
      hermite_rbf::hermite_rbf_param_specs());
}

}  // namespace

SKETCHLAB_PLUGIN(describe)
