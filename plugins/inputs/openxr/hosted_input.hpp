#pragma once
// The openxr input inside an application's OpenXR session (`sketchlab vr`):
// the ControllerInput (sketchlab/plugin/controller_input.hpp) the plugin
// host makes for a viewer. The application owns the instance and session;
// this owns the action set (xr_actions.hpp) and the gesture interpreter,
// with the hand menu on (the viewer draws it from state()).
#include <deque>
#include <memory>
#include <optional>

#include "gesture_interpreter.hpp"
#include "sketchlab/plugin/controller_input.hpp"
#include "sketchlab/plugin/params.hpp"
#include "xr_actions.hpp"

namespace sketchlab::openxr {

class HostedInput : public ControllerInput {
 public:
  // `params` validated against input_param_specs().
  explicit HostedInput(const Params& params);
  ~HostedInput() override;

  RecordingHeader header() const override;
  NextEvent next() override;

  void create_actions(XrHandleValue instance) override;
  // Throws std::logic_error before create_actions.
  void attach(const XrSessionHandles& session, const Workspace& workspace, std::size_t stack_count) override;
  // Throws std::logic_error before attach; does nothing once closed.
  void read_frame(std::int64_t display_time, double seconds, bool focused) override;
  ControllerState state() const override;
  void close() override;

 private:
  InputSettings settings_;
  std::unique_ptr<ControllerActions> actions_;
  std::optional<GestureInterpreter> interpreter_;
  XrSession session_ = XR_NULL_HANDLE;
  XrSpace base_ = XR_NULL_HANDLE, view_ = XR_NULL_HANDLE;
  ControllerFrame frame_;  // the last one read
  std::deque<Event> pending_;
  bool closed_ = false;
};

}  // namespace sketchlab::openxr
