// Synthetic sessions with ground truth: a curve network (built-in model or
// the sharp features of a mesh) drawn stroke by stroke with modelled human
// error, each stroke followed by its intended curve and relations. The whole
// session is generated when the input is created (deterministic from the
// seed), so bad parameters fail before anything runs.
#include "session_synthesis.hpp"
#include "sketchlab/plugin/plugin_api.hpp"
#include "sketchlab/plugin/recording_input.hpp"
#include "synthetic_params.hpp"

namespace {

using namespace sketchlab;

class SyntheticInput : public RecordingInput {
 public:
  explicit SyntheticInput(const Params& p)
      : RecordingInput(synthetic::synthesize_session(synthetic::synthesis_params(p))) {}
};

PluginDescriptor describe() {
  return input_descriptor<SyntheticInput>(
      "synthetic", "1.0",
      "synthetic VR or tablet sessions drawn from a ground-truth curve network, with ground truth",
      synthetic::synthetic_param_specs());
}

}  // namespace

SKETCHLAB_PLUGIN(describe)
