// The openxr input plugin: controllers of an OpenXR headset as session
// events (gesture_interpreter.hpp). On its own it opens a headless OpenXR
// session (XR_MND_headless); `sketchlab vr` gets a ControllerInput
// (hosted_input.hpp) that reads the same actions inside its rendering
// session instead.
#include <deque>

#include "headless_session.hpp"
#include "hosted_input.hpp"
#include "sketchlab/plugin/plugin_api.hpp"

namespace {

using namespace sketchlab;

class OpenXrInput : public Input {
 public:
  explicit OpenXrInput(const Params& p)
      : session_(openxr::settings_from_params(p), Workspace{}) {
    header_.units = "m";
    header_.source = {{"input", "openxr"},
                      {"runtime", session_.runtime_name()},
                      {"timing", session_.clock_timed() ? "runtime clock" : "xrWaitFrame"}};
  }
  RecordingHeader header() const override { return header_; }
  // Waits for the controllers at most this long per call: a live input
  // returns nothing now and then, so its caller can notice a stop request.
  NextEvent next() override {
    if (pending_.empty() && !session_.ended())
      for (auto& e : session_.next_events(std::chrono::milliseconds(50))) pending_.push_back(std::move(e));
    if (pending_.empty()) return session_.ended() ? NextEvent::ended() : NextEvent::not_ready();
    Event e = std::move(pending_.front());
    pending_.pop_front();
    return e;
  }
  void request_stop() override { session_.request_exit(); }

 private:
  openxr::HeadlessSession session_;
  RecordingHeader header_;
  std::deque<Event> pending_;
};

PluginDescriptor describe() {
  return controller_input_descriptor<OpenXrInput, openxr::HostedInput>(
      "openxr", "1.0",
      "OpenXR controllers: draw with the trigger (pressure), grab to move, two-hand zoom, commands on buttons",
      openxr::input_param_specs());
}

}  // namespace

SKETCHLAB_PLUGIN(describe)
