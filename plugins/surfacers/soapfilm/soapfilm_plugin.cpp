// CASSIE's surfacing (CHI'21 §5, thesis §3.3, Appendix B) as a surfacer
// plugin: local cycle search after each edit, manual patches, soap-film
// meshes.
#include "sketchlab/plugin/plugin_api.hpp"
#include "soapfilm_surfacer.hpp"

namespace {

using namespace sketchlab;

class SoapfilmSurfacer : public Surfacer {
 public:
  explicit SoapfilmSurfacer(const Params& p) : params_(soapfilm::soapfilm_params(p)) {}
  SurfaceUpdate update(const Sketch& sketch, const Edit& last) override {
    return soapfilm::soapfilm_update(sketch, last, params_);
  }
  SurfaceUpdate command(const Sketch& sketch, const SurfaceCommand& command) override {
    return soapfilm::soapfilm_command(sketch, command, params_);
  }

 private:
  soapfilm::SoapfilmParams params_;
};

PluginDescriptor describe() {
  return surfacer_descriptor<SoapfilmSurfacer>(
      "soapfilm", "1.0",
      "CASSIE surfacing: local cycle detection on the curve network, soap-film patches (CGAL)",
      soapfilm::soapfilm_param_specs());
}

}  // namespace

SKETCHLAB_PLUGIN(describe)
