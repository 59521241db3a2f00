#include "hosted_input.hpp"

#include <stdexcept>

#include "controller_state.hpp"

namespace sketchlab::openxr {

HostedInput::HostedInput(const Params& params) : settings_(settings_from_params(params)) {
  settings_.hand_menu = true;  // the application draws it (ControllerState::menu)
}

HostedInput::~HostedInput() = default;

RecordingHeader HostedInput::header() const {
  RecordingHeader h;
  h.units = "m";
  h.source = {{"input", "openxr"}};
  return h;
}

NextEvent HostedInput::next() {
  if (pending_.empty()) return closed_ ? NextEvent::ended() : NextEvent::not_ready();
  Event e = std::move(pending_.front());
  pending_.pop_front();
  return e;
}

void HostedInput::create_actions(XrHandleValue instance) {
  actions_ = std::make_unique<ControllerActions>(xr_handle<XrInstance>(instance), settings_);
}

void HostedInput::attach(const XrSessionHandles& session, const Workspace& workspace, std::size_t stack_count) {
  if (!actions_) throw std::logic_error("openxr input: attach before create_actions");
  session_ = xr_handle<XrSession>(session.session);
  base_ = xr_handle<XrSpace>(session.base_space);
  view_ = xr_handle<XrSpace>(session.view_space);
  actions_->attach(session_);
  interpreter_.emplace(settings_, workspace);
  interpreter_->set_stack_count(stack_count);
}

void HostedInput::read_frame(std::int64_t display_time, double seconds, bool focused) {
  if (!interpreter_) throw std::logic_error("openxr input: read_frame before attach");
  if (closed_) return;
  frame_ = actions_->poll(session_, base_, view_, static_cast<XrTime>(display_time), seconds, focused);
  for (Event& e : interpreter_->step(frame_)) pending_.push_back(std::move(e));
}

ControllerState HostedInput::state() const {
  return interpreter_ ? controller_state(*interpreter_, frame_, settings_) : ControllerState{};
}

void HostedInput::close() {
  if (closed_) return;
  closed_ = true;
  if (!interpreter_) return;
  // What was being drawn when the session ended is kept.
  ControllerFrame last;
  last.focused = false;
  last.time = frame_.time;
  for (Event& e : interpreter_->step(last)) pending_.push_back(std::move(e));
}

}  // namespace sketchlab::openxr
