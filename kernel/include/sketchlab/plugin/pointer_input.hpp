#pragma once
// Live pointer inputs (tablet pen, mouse): the window that owns the device
// pushes pointer events and commands in; next() hands out the finished
// events in order. The window decodes its windowing system's events (the
// desktop viewer reads XInput2, with pressure from the device's valuators)
// and the input plugin turns them into strokes, so the plugin needs no
// windowing library and is testable on plain data. A viewer gets one from
// the plugin host (PluginHost::make_pointer_input, for plugins described with
// pointer_input_descriptor), never by casting across the plugin boundary.
#include <optional>

#include "sketchlab/plugin/input.hpp"

namespace sketchlab {

struct PointerSample {
  Vec2 pixel = Vec2::Zero();  // origin bottom-left (OpenGL window coordinates)
  double time = 0.0;          // seconds since the session started
  double pressure = 1.0;      // [0, 1]; 1 for devices without pressure
};

// How the next stroke is drawn: the camera at pen-down, the plane its pixels
// lie on (null: none, 2D only), the mode and the workspace zoom.
struct PointerContext {
  View view;
  std::optional<Vec4> draw_plane;  // (n, d), |n| = 1
  Layer layer = Layer::automatic;
  double workspace_scale = 1.0;
};

class PointerInput : public Input {
 public:
  // A stroke starts; a stroke still open is finished first.
  virtual void pen_down(const PointerSample& sample, const PointerContext& context) = 0;
  virtual void pen_move(const PointerSample& sample) = 0;
  // Ends the stroke; it becomes an event unless too short (then dropped).
  virtual void pen_up(const PointerSample& sample) = 0;
  // Drops the open stroke, if any.
  virtual void cancel() = 0;
  // Queues a non-stroke event (undo, mode, delete near, ...) behind the
  // events already queued; its time is clamped so times never decrease.
  virtual void command(const Event& event) = 0;
  // Id of the next stroke (a live session continuing a recording starts
  // after its last stroke id).
  virtual void set_next_stroke_id(StrokeId id) = 0;
  // Ends the input: next() ends once the queue is drained.
  virtual void close() = 0;
};

}  // namespace sketchlab
