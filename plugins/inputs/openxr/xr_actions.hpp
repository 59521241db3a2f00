#pragma once
// The openxr input's action set on a live OpenXR instance/session: creates
// the actions, suggests bindings for every supported profile
// (bindings.hpp), attaches them and reads one ControllerFrame per frame.
#include <openxr/openxr.h>

#include <array>
#include <string>

#include "controller_frame.hpp"
#include "input_settings.hpp"

namespace sketchlab::openxr {

class ControllerActions {
 public:
  // Throws XrError when the action set cannot be created. A profile the
  // runtime does not know is skipped (warning on stderr).
  ControllerActions(XrInstance instance, const InputSettings& settings);
  ~ControllerActions();
  ControllerActions(const ControllerActions&) = delete;
  ControllerActions& operator=(const ControllerActions&) = delete;

  // Attaches the action set to `session` and creates the hand spaces.
  void attach(XrSession session);

  // Syncs the actions and reads the controllers at `time`, poses relative
  // to `base` (stage or local space); the head from `view_space`. When
  // `focused` is false no input is read (the frame says so).
  ControllerFrame poll(XrSession session, XrSpace base, XrSpace view_space, XrTime time,
                       double seconds, bool focused);

  // The interaction profile bound to the dominant hand ("" when none yet).
  std::string current_profile(XrSession session) const;

 private:
  XrInstance instance_;
  InputSettings settings_;
  XrActionSet set_ = XR_NULL_HANDLE;
  XrAction draw_ = XR_NULL_HANDLE, grab_ = XR_NULL_HANDLE, pose_ = XR_NULL_HANDLE;
  std::array<XrAction, command_count> commands_{};
  std::array<XrPath, 2> hand_paths_{};
  std::array<XrSpace, 2> hand_spaces_{XR_NULL_HANDLE, XR_NULL_HANDLE};
};

}  // namespace sketchlab::openxr
