#pragma once
// Turns controller frames into session events: strokes drawn with the
// draw button (its value as pressure), one-hand grab moving the workspace,
// two-hand zoom scaling it about the dominant hand, and commands on button
// presses.
//
// The workspace sits in the stage by a similarity x_stage = s R w + t
// (Placement). Samples are the dominant hand's aim pose mapped into
// workspace coordinates, so strokes are in workspace metres whatever the
// placement; only the zoom s is part of the sketch (WorkspaceEvent when a
// zoom ends, Stroke::workspace_scale), the rigid part is a view.
#include <optional>
#include <vector>

#include "controller_frame.hpp"
#include "sketchlab/event.hpp"
#include "sketchlab/workspace.hpp"

namespace sketchlab::openxr {

struct Placement {
  Quat rotation = Quat::Identity();
  Vec3 translation = Vec3::Zero();
  double scale = 1.0;
  Vec3 to_stage(const Vec3& w) const { return scale * (rotation * w) + translation; }
  Vec3 to_workspace(const Vec3& x) const { return rotation.conjugate() * (x - translation) / scale; }
};

class GestureInterpreter {
 public:
  GestureInterpreter(const InputSettings& settings, const Workspace& workspace);

  // Events caused by this frame, in order (zoom end, stroke end, commands),
  // all at frame.time. Times must not decrease (earlier frames are ignored,
  // as are negative or non-finite times); a non-finite or absurd pose counts
  // as not tracked. Every event is one the recording format accepts.
  std::vector<Event> step(const ControllerFrame& frame);

  const Placement& placement() const { return placement_; }
  const Workspace& workspace() const { return workspace_; }
  Layer mode() const { return mode_; }
  bool correction_enabled() const { return correction_; }
  // Samples of the stroke being drawn (workspace), empty when not drawing.
  const std::vector<Sample>& stroke_in_progress() const { return samples_; }

 private:
  void update_grab(const ControllerFrame& frame, std::vector<Event>& events);
  void update_draw(const ControllerFrame& frame, std::vector<Event>& events);
  void update_commands(const ControllerFrame& frame, std::vector<Event>& events);
  void end_stroke(double time, std::vector<Event>& events);
  void end_zoom(double time, std::vector<Event>& events);

  InputSettings settings_;
  Workspace workspace_;
  Placement placement_;
  Layer mode_;
  bool correction_ = true;
  double last_time_ = -1.0;
  StrokeId next_stroke_ = 1;

  bool drawing_ = false;
  std::vector<Sample> samples_;
  std::optional<View> head_view_;

  enum class Grab { none, one, two } grab_ = Grab::none;
  int grab_hand_ = 0;
  RigidPose grab_start_hand_;
  Placement grab_start_;
  double zoom_start_distance_ = 0.0;
  Vec3 zoom_anchor_ = Vec3::Zero();  // workspace point kept under the dominant hand
  double zoom_start_scale_ = 1.0;
  std::array<bool, command_count> previous_buttons_{};
};

}  // namespace sketchlab::openxr
