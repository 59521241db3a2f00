#pragma once
// Pointer events of one X window through XInput2: button press, motion and
// release of any master pointer, with the pen pressure read from the source
// device's "Abs Pressure" valuator when it has one (tablets), else 1 (mice,
// xdotool's XTEST pointer).
#include <map>
#include <optional>

namespace sketchlab::desktop {

struct XPointerEvent {
  enum class Type { press, release, motion } type = Type::motion;
  int button = 0;         // 1 left, 2 middle, 3 right, 4/5 wheel; 0 for motion
  double x = 0, y = 0;    // window pixels, origin top-left (X convention)
  double pressure = 1.0;  // [0, 1]
  bool shift = false, control = false;  // modifier keys held
  unsigned long time_ms = 0;  // X server time
};

class XPointer {
 public:
  // Selects XI2 pointer events on `window`; throws std::runtime_error when
  // the server lacks XInput 2.0.
  // `display` is the Display* and `window` the Window (kept opaque so that
  // VTK code including this header does not see Xlib's macros).
  XPointer(void* display, unsigned long window);
  // Decodes `xevent` (an XEvent*) when it is one of ours (XI2 generic
  // event), else nullopt.
  std::optional<XPointerEvent> decode(void* xevent);

 private:
  struct PressureAxis {
    int number = -1;  // valuator index, -1: the device has none
    double min = 0, max = 1;
  };
  const PressureAxis& pressure_axis(int device);

  void* display_;
  int opcode_ = -1;
  std::map<int, PressureAxis> axes_;  // by source device id
};

}  // namespace sketchlab::desktop
