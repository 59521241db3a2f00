#include "gesture_interpreter.hpp"

#include <algorithm>
#include <cmath>

#include "sketchlab/recording/event_json.hpp"

namespace sketchlab::openxr {
namespace {

Layer next_mode(Layer mode) {
  switch (mode) {
    case Layer::scaffold: return Layer::shape;
    case Layer::shape: return Layer::free;
    default: return Layer::scaffold;
  }
}

// A glitching runtime may report NaN, infinite or absurd poses (found by
// fuzz/fuzz_openxr_input): they are taken as lost tracking, so that nothing
// the recording format refuses comes out.
bool plausible(const RigidPose& p) {
  const double q = p.orientation.norm();
  return p.position.allFinite() && p.position.cwiseAbs().maxCoeff() <= recording_max_coordinate &&
         std::isfinite(q) && q > 0.5 && q < 1.5;
}

// A workspace point the format can hold (a small zoom or a far placement
// can push a plausible hand beyond it).
bool recordable(const Vec3& w) { return w.allFinite() && w.cwiseAbs().maxCoeff() <= recording_max_coordinate; }

// World (workspace) -> eye of a head pose: (P^-1 H)^-1 = H^-1 P.
Mat4 head_view_matrix(const Placement& p, const RigidPose& head) {
  Mat4 placement = Mat4::Identity();
  placement.topLeftCorner<3, 3>() = p.scale * p.rotation.toRotationMatrix();
  placement.topRightCorner<3, 1>() = p.translation;
  Mat4 head_inverse = Mat4::Identity();
  const Mat3 r = head.orientation.conjugate().toRotationMatrix();
  head_inverse.topLeftCorner<3, 3>() = r;
  head_inverse.topRightCorner<3, 1>() = -(r * head.position);
  return head_inverse * placement;
}

}  // namespace

GestureInterpreter::GestureInterpreter(const InputSettings& settings, const Workspace& workspace)
    : settings_(settings), workspace_(workspace), mode_(settings.initial_mode) {
  placement_.scale = workspace.scale > 0.0 && std::isfinite(workspace.scale) ? workspace.scale : 1.0;
  workspace_.scale = placement_.scale;
}

std::vector<Event> GestureInterpreter::step(const ControllerFrame& raw) {
  std::vector<Event> events;
  if (!std::isfinite(raw.time) || raw.time < 0.0 || raw.time > recording_max_time || raw.time < last_time_)
    return events;
  last_time_ = raw.time;
  ControllerFrame frame = raw;
  frame.head_tracked = frame.head_tracked && plausible(frame.head);
  for (HandFrame& h : frame.hands) h.tracked = h.tracked && plausible(h.aim);
  if (!frame.focused) {
    // Focus lost: the user no longer sees or holds the session; what was
    // being drawn is kept, gestures end, buttons must be pressed again.
    end_zoom(frame.time, events);
    grab_ = Grab::none;
    end_stroke(frame.time, events);
    previous_buttons_.fill(true);
    trigger_was_pressed_ = true;  // a trigger held across the loss picks nothing
    hover_.reset();
    return events;
  }
  update_grab(frame, events);
  update_draw(frame, events);
  update_commands(frame, events);
  return events;
}

void GestureInterpreter::end_zoom(double time, std::vector<Event>& events) {
  if (grab_ != Grab::two) return;
  if (workspace_.scale != zoom_start_scale_) events.push_back({time, WorkspaceEvent{workspace_}});
}

void GestureInterpreter::update_grab(const ControllerFrame& frame, std::vector<Event>& events) {
  const int dom = static_cast<int>(settings_.dominant), other = 1 - dom;
  const auto held = [&](int h) { return frame.hands[h].tracked && frame.hands[h].grab; };
  const Grab want = held(0) && held(1) ? Grab::two : held(0) || held(1) ? Grab::one : Grab::none;
  if (want != Grab::two) end_zoom(frame.time, events);
  if (want == Grab::two) {
    const Vec3 pd = frame.hands[dom].aim.position, po = frame.hands[other].aim.position;
    const double d = (pd - po).norm();
    if (grab_ != Grab::two) {
      grab_ = Grab::two;
      zoom_start_distance_ = d;
      zoom_start_scale_ = placement_.scale;
      zoom_anchor_ = placement_.to_workspace(pd);
    }
    // Zoom: s = s0 d / d0 about the dominant hand (CASSIE's two-hand scaling).
    if (zoom_start_distance_ > 1e-6 && std::isfinite(d)) {
      placement_.scale = std::clamp(zoom_start_scale_ * d / zoom_start_distance_, settings_.min_scale,
                                    settings_.max_scale);
      placement_.translation = pd - placement_.scale * (placement_.rotation * zoom_anchor_);
      workspace_.scale = placement_.scale;
    }
    return;
  }
  if (want == Grab::one) {
    const int h = held(0) ? 0 : 1;
    if (grab_ != Grab::one || grab_hand_ != h) {
      grab_ = Grab::one;
      grab_hand_ = h;
      grab_start_hand_ = frame.hands[h].aim;
      grab_start_ = placement_;
    }
    // The workspace moves rigidly with the hand: x' = H H0^-1 x.
    const RigidPose& now = frame.hands[h].aim;
    const Quat turn = settings_.grab_rotates
                          ? (now.orientation * grab_start_hand_.orientation.conjugate()).normalized()
                          : Quat::Identity();
    placement_.rotation = (turn * grab_start_.rotation).normalized();
    placement_.translation = turn * (grab_start_.translation - grab_start_hand_.position) + now.position;
    return;
  }
  grab_ = Grab::none;
}

void GestureInterpreter::end_stroke(double time, std::vector<Event>& events) {
  if (!drawing_) return;
  drawing_ = false;
  // A stroke needs two samples apart (the recording format refuses others).
  const bool usable = samples_.size() >= 2 &&
                      std::any_of(samples_.begin() + 1, samples_.end(), [&](const Sample& s) {
                        return (s.position - samples_.front().position).norm() > 0.0;
                      });
  if (usable) {
    Stroke stroke;
    stroke.id = next_stroke_++;
    stroke.samples = std::move(samples_);
    stroke.layer = mode_;
    stroke.view = head_view_;
    stroke.workspace_scale = workspace_.scale;
    events.push_back({time, StrokeEvent{std::move(stroke)}});
  }
  samples_.clear();
  head_view_.reset();
}

void GestureInterpreter::update_draw(const ControllerFrame& frame, std::vector<Event>& events) {
  const HandFrame& hand = frame.hands[static_cast<int>(settings_.dominant)];
  const bool pressed = std::isfinite(frame.draw_value) && frame.draw_value >= settings_.draw_threshold;
  const bool dominant_grabbing = grab_ != Grab::none && (grab_ == Grab::two || grab_hand_ == static_cast<int>(settings_.dominant));
  if (drawing_ && (!pressed || dominant_grabbing)) end_stroke(frame.time, events);
  const bool rising = pressed && !trigger_was_pressed_;
  trigger_was_pressed_ = pressed;
  if (!pressed) trigger_used_ = false;
  const HandFrame& holder = frame.hands[1 - static_cast<int>(settings_.dominant)];
  hover_.reset();
  if (settings_.hand_menu && !drawing_ && hand.tracked && holder.tracked)
    hover_ = menu_item_at(holder.aim, hand.aim.position);
  if (!drawing_ && rising && !dominant_grabbing && (hover_ || tool_ != Tool::draw)) {
    trigger_used_ = true;
    if (hover_)
      pick(*hover_, frame.time, events);
    else
      use_tool(tool_, hand, frame.time, events);
  }
  if (trigger_used_ || tool_ != Tool::draw) return;
  if (!drawing_ && pressed && !dominant_grabbing && hand.tracked) drawing_ = true;
  if (!drawing_ || !hand.tracked) return;
  Sample s;
  s.position = placement_.to_workspace(hand.aim.position);
  if (!recordable(s.position)) return;
  s.time = frame.time;
  s.pressure = std::clamp(frame.draw_value, 0.0, 1.0);
  s.orientation = (placement_.rotation.conjugate() * hand.aim.orientation).normalized();
  samples_.push_back(s);
  if (frame.head_tracked) {
    View v;
    v.view = head_view_matrix(placement_, frame.head);
    head_view_ = v;
  }
}

void GestureInterpreter::pick(MenuItem item, double time, std::vector<Event>& events) {
  const auto set_mode = [&](Layer layer) {
    tool_ = Tool::draw;
    if (mode_ == layer) return;
    mode_ = layer;
    events.push_back({time, ModeEvent{mode_}});
  };
  switch (item) {
    case MenuItem::scaffold: set_mode(Layer::scaffold); break;
    case MenuItem::shape: set_mode(Layer::shape); break;
    case MenuItem::free: set_mode(Layer::free); break;
    case MenuItem::patch: tool_ = tool_ == Tool::patch ? Tool::draw : Tool::patch; break;
    case MenuItem::erase: tool_ = tool_ == Tool::erase ? Tool::draw : Tool::erase; break;
    case MenuItem::correction:
      correction_ = !correction_;
      events.push_back({time, CorrectionEvent{correction_}});
      break;
    case MenuItem::undo: events.push_back({time, UndoEvent{}}); break;
    case MenuItem::redo: events.push_back({time, RedoEvent{}}); break;
    case MenuItem::next_stack: view_.stack = (view_.stack + 1) % stack_count_; break;
    case MenuItem::compare: view_.compare = !view_.compare && stack_count_ >= 2; break;
    case MenuItem::raw_strokes: view_.raw_strokes = !view_.raw_strokes; break;
    case MenuItem::rejected: view_.rejected = !view_.rejected; break;
  }
}

void GestureInterpreter::use_tool(Tool tool, const HandFrame& hand, double time, std::vector<Event>& events) {
  if (!hand.tracked) return;
  const Vec3 point = placement_.to_workspace(hand.aim.position);
  if (!recordable(point)) return;
  if (tool == Tool::patch) events.push_back({time, AddPatchEvent{point}});
  if (tool == Tool::erase)
    events.push_back({time, DeleteNearEvent{point, scaled_threshold(settings_.delete_radius, workspace_.scale)}});
}

void GestureInterpreter::update_commands(const ControllerFrame& frame, std::vector<Event>& events) {
  const HandFrame& hand = frame.hands[static_cast<int>(settings_.dominant)];
  for (std::size_t i = 0; i < command_count; ++i) {
    const bool pressed = frame.buttons[i] && !previous_buttons_[i];
    previous_buttons_[i] = frame.buttons[i];
    if (!pressed) continue;
    switch (static_cast<Command>(i)) {
      case Command::undo: events.push_back({frame.time, UndoEvent{}}); break;
      case Command::redo: events.push_back({frame.time, RedoEvent{}}); break;
      case Command::mode:
        mode_ = next_mode(mode_);
        events.push_back({frame.time, ModeEvent{mode_}});
        break;
      case Command::delete_nearest: use_tool(Tool::erase, hand, frame.time, events); break;
      case Command::add_patch: use_tool(Tool::patch, hand, frame.time, events); break;
      case Command::toggle_correction:
        correction_ = !correction_;
        events.push_back({frame.time, CorrectionEvent{correction_}});
        break;
    }
  }
}

}  // namespace sketchlab::openxr
