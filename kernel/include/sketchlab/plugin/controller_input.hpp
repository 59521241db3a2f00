#pragma once
// Live controller inputs (OpenXR motion controllers) driven by an
// application that renders: the application owns the OpenXR instance and
// session, the input plugin owns the action set and turns controller poses
// and buttons into session events, as hello_xr splits its program from its
// input code. The application gets one from the plugin host
// (PluginHost::make_controller_input, for plugins described with
// controller_input_descriptor), never by linking the plugin's code.
//
// The calls follow the OpenXR lifecycle:
//   1. create_actions(instance): after xrCreateInstance, before
//      xrCreateSession (the action set and its suggested bindings);
//   2. attach(session, ...): once the session exists (xrAttachSessionActionSets,
//      the hand spaces);
//   3. read_frame(time, ...): once per frame, between xrWaitFrame and
//      xrEndFrame; the events this frame caused are then ready in next();
//   4. close(): the session is over; next() hands out what is left, then ends.
// A failure (a call the runtime refuses) sets error() and ends the input;
// the application checks error() after create_actions and attach. The
// OpenXR handles travel as their 64-bit values (XR_DEFINE_HANDLE), so this
// header needs no OpenXR header; both sides call the same loader.
#include <array>
#include <cstdint>
#include <string>
#include <type_traits>
#include <vector>

#include "sketchlab/plugin/input.hpp"
#include "sketchlab/sample.hpp"
#include "sketchlab/stroke.hpp"
#include "sketchlab/workspace.hpp"

namespace sketchlab {

// An OpenXR handle as a number (0 is XR_NULL_HANDLE) and back.
using XrHandleValue = std::uint64_t;
template <class Handle>
XrHandleValue xr_handle_value(Handle handle) {
  if constexpr (std::is_pointer_v<Handle>)
    return static_cast<XrHandleValue>(reinterpret_cast<std::uintptr_t>(handle));
  else
    return static_cast<XrHandleValue>(handle);
}
template <class Handle>
Handle xr_handle(XrHandleValue value) {
  if constexpr (std::is_pointer_v<Handle>)
    return reinterpret_cast<Handle>(static_cast<std::uintptr_t>(value));
  else
    return static_cast<Handle>(value);
}

// The application's session: `base` is the space poses are reported in
// (STAGE, or LOCAL where there is no stage), `view` the headset's.
struct XrSessionHandles {
  XrHandleValue session = 0;
  XrHandleValue base_space = 0;
  XrHandleValue view_space = 0;
};

struct Pose {
  Vec3 position = Vec3::Zero();
  Quat orientation = Quat::Identity();
};

// Where the workspace sits in the stage: x_stage = scale * rotation * w +
// translation. Only the zoom is part of the sketch (Workspace::scale); the
// rigid part is how the user holds it.
struct StagePlacement {
  Quat rotation = Quat::Identity();
  Vec3 translation = Vec3::Zero();
  double scale = 1.0;
  Vec3 to_stage(const Vec3& w) const { return scale * (rotation * w) + translation; }
  Vec3 to_workspace(const Vec3& x) const { return rotation.conjugate() * (x - translation) / scale; }
};

// What the drawing trigger does now: draw strokes, add a patch at the tip,
// or delete the curve nearest the tip.
enum class ControllerTool { draw, patch, erase };

// What the user chose to see (never recorded: every stack sees every event,
// the application picks what to show).
struct ControllerView {
  std::size_t stack = 0;    // index of the stack shown
  bool compare = false;     // the next stack's curves overlaid on the shown one's
  bool raw_strokes = true;  // raw strokes drawn faintly under the curves
  bool rejected = false;    // constraint candidates the corrector rejected flashed too
  bool operator==(const ControllerView&) const = default;
};

// One item of a menu held by a hand, placed in that hand's aim frame
// (metres; x right, y up, +z towards the user).
struct ControllerMenuItem {
  std::string label;
  Vec3 centre = Vec3::Zero();
  bool active = false;   // the mode, tool or toggle it sets is on
  bool hovered = false;  // under the drawing hand's tip this frame
};

struct ControllerMenu {
  std::vector<ControllerMenuItem> items;  // empty: the input shows no menu
  double cell = 0.0;                      // side of an item's square, m
  Vec3 centre = Vec3::Zero();             // the panel's centre (aim frame)
  Vec2 half_size = Vec2::Zero();          // its half extents along x and y
};

struct ControllerHand {
  bool tracked = false;
  Pose aim;  // stage
};

// What the application draws of the input after a frame: everything in
// stage space (metres) unless said otherwise.
struct ControllerState {
  ControllerHand pen;     // the drawing (dominant) hand
  ControllerHand holder;  // the other hand, which holds the menu
  StagePlacement placement;
  Workspace workspace;    // as the session's events left it (zoom included)
  Layer mode = Layer::automatic;
  bool correction = true;
  ControllerTool tool = ControllerTool::draw;
  std::vector<Sample> stroke;  // the stroke being drawn (workspace), empty when none
  ControllerMenu menu;
  ControllerView view;
};

class ControllerInput : public Input {
 public:
  // Creates the action set on `instance` and suggests its bindings for
  // every interaction profile it knows (profiles the runtime does not know
  // are skipped). Before the application creates its session.
  virtual void create_actions(XrHandleValue instance) = 0;
  // Attaches the actions to the application's session. The session starts
  // with `workspace` (grid, mirror, zoom); the menu cycles through
  // `stack_count` (>= 1) stacks.
  virtual void attach(const XrSessionHandles& session, const Workspace& workspace, std::size_t stack_count) = 0;
  // Syncs the actions and reads the controllers at `display_time` (the
  // frame's predicted XrTime, ns); the events it causes are stamped
  // `seconds` (since the session began, non-decreasing). When `focused` is
  // false (the session has no input focus) nothing is read: hands count as
  // untracked and buttons as released.
  virtual void read_frame(std::int64_t display_time, double seconds, bool focused) = 0;
  // After the last read_frame.
  virtual ControllerState state() const = 0;
  // The session is over: what was being drawn becomes an event (at the
  // last frame's time); next() ends once the events are handed out.
  virtual void close() = 0;
};

}  // namespace sketchlab
