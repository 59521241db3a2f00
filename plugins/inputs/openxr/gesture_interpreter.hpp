#pragma once
// Turns controller frames into session events: strokes drawn with the
// draw button (its value as pressure), one-hand grab moving the workspace,
// two-hand zoom scaling it about the dominant hand, and commands on button
// presses; the hand menu (hand_menu.hpp) picked with the draw trigger.
//
// The workspace sits in the stage by a similarity x_stage = s R w + t
// (Placement). Samples are the dominant hand's aim pose mapped into
// workspace coordinates, so strokes are in workspace metres whatever the
// placement; only the zoom s is part of the sketch (WorkspaceEvent when a
// zoom ends, Stroke::workspace_scale), the rigid part is a view.
#include <optional>
#include <vector>

#include "controller_frame.hpp"
#include "hand_menu.hpp"
#include "sketchlab/event.hpp"
#include "sketchlab/workspace.hpp"

namespace sketchlab::openxr {

using Placement = StagePlacement;

// What the draw trigger does (set from the hand menu): draw strokes, add a
// patch at the tip, or delete the curve nearest the tip (CASSIE's
// delete-nearest, radius delete_radius / s).
using Tool = ControllerTool;

// What the hand menu sets that is view state only (never recorded: every
// stack sees every event, the viewer picks what to show).
using MenuView = ControllerView;

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

  // The hand menu (when settings.hand_menu). Items act on the draw trigger's
  // rising edge while the dominant aim point is over them (both hands
  // tracked, not drawing); the
  // press is then used up until the trigger is released. `stacks` (>= 1) is
  // how many stacks next_stack cycles through; compare needs two.
  void set_stack_count(std::size_t stacks) { stack_count_ = stacks > 0 ? stacks : 1; }
  Tool tool() const { return tool_; }
  const MenuView& menu_view() const { return view_; }
  // The item under the dominant aim point this frame (for highlighting).
  std::optional<MenuItem> menu_hover() const { return hover_; }

 private:
  void update_grab(const ControllerFrame& frame, std::vector<Event>& events);
  void update_draw(const ControllerFrame& frame, std::vector<Event>& events);
  void update_commands(const ControllerFrame& frame, std::vector<Event>& events);
  void end_stroke(double time, std::vector<Event>& events);
  void end_zoom(double time, std::vector<Event>& events);
  void pick(MenuItem item, double time, std::vector<Event>& events);
  void use_tool(Tool tool, const HandFrame& hand, double time, std::vector<Event>& events);

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

  Tool tool_ = Tool::draw;
  MenuView view_;
  std::size_t stack_count_ = 1;
  std::optional<MenuItem> hover_;
  bool trigger_was_pressed_ = false;
  bool trigger_used_ = false;  // this press picked an item or used a tool
};

}  // namespace sketchlab::openxr
