#include "x_pointer.hpp"

#include <X11/Xlib.h>
#include <X11/extensions/XInput2.h>

#include <algorithm>
#include <cstring>
#include <stdexcept>

namespace sketchlab::desktop {

XPointer::XPointer(void* display_handle, unsigned long window) : display_(display_handle) {
  auto* display = static_cast<Display*>(display_handle);
  int event = 0, error = 0;
  if (!XQueryExtension(display, "XInputExtension", &opcode_, &event, &error))
    throw std::runtime_error("the X server has no XInput extension");
  int major = 2, minor = 0;
  if (XIQueryVersion(display, &major, &minor) != Success)
    throw std::runtime_error("the X server lacks XInput 2.0");
  unsigned char bits[XIMaskLen(XI_LASTEVENT)] = {};
  XISetMask(bits, XI_ButtonPress);
  XISetMask(bits, XI_ButtonRelease);
  XISetMask(bits, XI_Motion);
  XIEventMask mask{XIAllMasterDevices, static_cast<int>(sizeof bits), bits};
  XISelectEvents(display, window, &mask, 1);
  XFlush(display);
}

const XPointer::PressureAxis& XPointer::pressure_axis(int device) {
  if (auto it = axes_.find(device); it != axes_.end()) return it->second;
  PressureAxis axis;
  auto* display = static_cast<Display*>(display_);
  const Atom pressure = XInternAtom(display, "Abs Pressure", True);
  int count = 0;
  if (XIDeviceInfo* info = XIQueryDevice(display, device, &count)) {
    for (int c = 0; c < info->num_classes && pressure != None; ++c) {
      if (info->classes[c]->type != XIValuatorClass) continue;
      const auto* v = reinterpret_cast<const XIValuatorClassInfo*>(info->classes[c]);
      if (v->label == pressure && v->max > v->min) axis = {v->number, v->min, v->max};
    }
    XIFreeDeviceInfo(info);
  }
  return axes_.emplace(device, axis).first->second;
}

std::optional<XPointerEvent> XPointer::decode(void* xevent) {
  auto* display = static_cast<Display*>(display_);
  XGenericEventCookie* cookie = &static_cast<XEvent*>(xevent)->xcookie;
  if (cookie->type != GenericEvent || cookie->extension != opcode_) return std::nullopt;
  if (!XGetEventData(display, cookie)) return std::nullopt;
  std::optional<XPointerEvent> out;
  if (cookie->evtype == XI_ButtonPress || cookie->evtype == XI_ButtonRelease ||
      cookie->evtype == XI_Motion) {
    const auto* e = static_cast<const XIDeviceEvent*>(cookie->data);
    XPointerEvent p;
    p.type = cookie->evtype == XI_ButtonPress     ? XPointerEvent::Type::press
             : cookie->evtype == XI_ButtonRelease ? XPointerEvent::Type::release
                                                  : XPointerEvent::Type::motion;
    p.button = cookie->evtype == XI_Motion ? 0 : e->detail;
    p.x = e->event_x;
    p.y = e->event_y;
    p.shift = (e->mods.effective & ShiftMask) != 0;
    p.control = (e->mods.effective & ControlMask) != 0;
    p.time_ms = e->time;
    const PressureAxis& axis = pressure_axis(e->sourceid);
    if (axis.number >= 0 && axis.number < e->valuators.mask_len * 8 &&
        XIMaskIsSet(e->valuators.mask, axis.number)) {
      // Values are packed: one per set bit below ours.
      int index = 0;
      for (int i = 0; i < axis.number; ++i) index += XIMaskIsSet(e->valuators.mask, i) ? 1 : 0;
      p.pressure = std::clamp((e->valuators.values[index] - axis.min) / (axis.max - axis.min), 0.0, 1.0);
    }
    out = p;
  }
  XFreeEventData(display, cookie);
  return out;
}

}  // namespace sketchlab::desktop
