// libFuzzer harness: what the openxr input makes of a runtime's data. The
// bytes choose the input's button settings (parsed like the stack's
// parameters) and then a run of controller frames: poses, the trigger,
// buttons, focus and times, including the NaN, infinite and huge values a
// glitching runtime may return. Contract: bad settings are
// std::invalid_argument or ParamError; the gesture interpreter never throws, and every
// event it produces is one the recording format accepts (so `record` and
// `vr` can always write it).
#include "fuzz_support.hpp"
#include "gesture_interpreter.hpp"
#include "sketchlab/recording/event_json.hpp"

using namespace sketchlab;
using namespace sketchlab::openxr;

namespace {

std::string button(fuzz::Bytes& in) {
  static const char* const names[] = {"left/x", "right/a", "left/trigger", "right/thumbstick", "left/menu",
                                      "right/b", "up/x",   "left/",        "right/trackpad",  ""};
  return names[in.byte() % 10];
}

RigidPose pose(fuzz::Bytes& in) {
  RigidPose p;
  p.position = Vec3(in.number(3.0), in.number(3.0), in.number(3.0));
  p.orientation = Quat(in.number(1.0), in.number(1.0), in.number(1.0), in.number(1.0));
  if (in.flag()) p.orientation.normalize();
  return p;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::Bytes in(data, size);
  const std::vector<ParamSpec> specs = input_param_specs();
  std::map<std::string, ParamValue> given;
  given["draw_button"] = in.flag() ? button(in) : std::string("right/trigger");
  given["undo_button"] = in.flag() ? button(in) : std::string("left/x");
  given["dominant_hand"] = std::string(in.flag() ? "left" : "right");
  InputSettings settings;
  try {
    settings = settings_from_params(validate_params(specs, given));
  } catch (const std::invalid_argument&) {
    return 0;
  } catch (const ParamError&) {
    return 0;
  }
  Workspace workspace;
  GestureInterpreter interpreter(settings, workspace);
  double time = 0.0;
  while (!in.empty()) {
    ControllerFrame f;
    const std::uint8_t step = in.byte();
    time = step == 255 ? in.number(10.0) : time + step * 1e-3;  // now and then a jump, even backwards
    f.time = time;
    f.focused = in.byte() != 0;
    f.head_tracked = in.flag();
    f.head = pose(in);
    for (auto& h : f.hands) {
      h.tracked = in.flag();
      h.aim = pose(in);
      h.grab = in.flag();
    }
    f.draw_value = in.number(1.0);
    for (auto& b : f.buttons) b = in.flag();
    for (const Event& e : interpreter.step(f)) {
      try {
        to_json_line(e);
      } catch (const std::invalid_argument& why) {
        fuzz::broken(std::string("the interpreter produced an event recordings refuse: ") + why.what());
      }
    }
  }
  return 0;
}
