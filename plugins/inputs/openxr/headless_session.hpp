#pragma once
// An OpenXR session without graphics (XR_MND_headless), for the openxr input
// used on its own (`sketchlab record --input openxr`): controllers only, no
// picture. The VR viewer has its own session with rendering and uses the
// same ControllerActions and GestureInterpreter.
#include <openxr/openxr.h>

#include <memory>
#include <string>
#include <vector>

#include "gesture_interpreter.hpp"
#include "xr_actions.hpp"

namespace sketchlab::openxr {

class HeadlessSession {
 public:
  // Throws XrError with a message saying what is missing (no runtime, no
  // XR_MND_headless, session refused).
  explicit HeadlessSession(const InputSettings& settings, const Workspace& workspace);
  ~HeadlessSession();
  HeadlessSession(const HeadlessSession&) = delete;
  HeadlessSession& operator=(const HeadlessSession&) = delete;

  // Runs frames until at least one event is produced or the session ends;
  // returns the events (empty only once ended()).
  std::vector<Event> next_events();
  bool ended() const { return ended_; }
  const std::string& runtime_name() const { return runtime_name_; }

 private:
  bool poll_state();  // false once the session is over
  XrInstance instance_ = XR_NULL_HANDLE;
  XrSystemId system_ = XR_NULL_SYSTEM_ID;
  XrSession session_ = XR_NULL_HANDLE;
  XrSpace base_ = XR_NULL_HANDLE, view_ = XR_NULL_HANDLE;
  std::unique_ptr<ControllerActions> actions_;
  GestureInterpreter interpreter_;
  XrSessionState state_ = XR_SESSION_STATE_UNKNOWN;
  bool running_ = false, ended_ = false;
  XrTime start_ = 0;
  double last_seconds_ = 0.0;
  std::string runtime_name_;
};

}  // namespace sketchlab::openxr
