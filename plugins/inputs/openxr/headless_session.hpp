#pragma once
// An OpenXR session without graphics (XR_MND_headless), for the openxr input
// used on its own (`sketchlab record --input openxr`): controllers only, no
// picture. The VR viewer has its own session with rendering and uses the
// same ControllerActions and GestureInterpreter.
//
// Time: in a headless session the frame functions are optional, and Monado
// returns from xrWaitFrame at once with display time 0 (its xrBeginFrame then
// fails: no counted wait). When the runtime offers XR_KHR_convert_timespec_time
// the session skips the frame functions, polls the controllers at
// InputSettings::headless_poll_hz and takes each poll's time from the
// runtime's clock. Otherwise it runs the frame loop, timed by xrWaitFrame.
#include <openxr/openxr.h>

#include <chrono>
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

  // Polls until at least one event is produced, the session ends, or about
  // `wait` has passed; returns the events (empty when nothing happened).
  // Once the session ended, what was in progress comes out and ended() is
  // true.
  std::vector<Event> next_events(std::chrono::milliseconds wait);
  bool ended() const { return ended_; }
  // Asks the runtime to end the session (xrRequestExitSession); the stroke
  // being drawn is kept. A no-op when it is not running.
  void request_exit();
  const std::string& runtime_name() const { return runtime_name_; }
  // True when time comes from the runtime's clock, not xrWaitFrame.
  bool clock_timed() const { return convert_time_ != nullptr; }

 private:
  bool poll_state();  // false once the session is over
  // The controllers at `time` (runtime clock), as events.
  std::vector<Event> poll_controllers(XrTime time);
  XrTime runtime_now() const;
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
  PFN_xrVoidFunction convert_time_ = nullptr;  // xrConvertTimespecTimeToTimeKHR
  std::chrono::steady_clock::duration poll_period_;
  std::chrono::steady_clock::time_point next_poll_;
};

}  // namespace sketchlab::openxr
