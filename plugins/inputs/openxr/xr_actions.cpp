#include "xr_actions.hpp"

#include <cstring>
#include <iostream>
#include <map>
#include <vector>

#include "bindings.hpp"
#include "xr_result.hpp"

namespace sketchlab::openxr {
namespace {

XrPath path_of(XrInstance instance, const std::string& text) {
  XrPath path = XR_NULL_PATH;
  check(xrStringToPath(instance, text.c_str(), &path), ("xrStringToPath(" + text + ")").c_str());
  return path;
}

XrAction make_action(XrActionSet set, const char* name, const char* localized, XrActionType type,
                     const std::array<XrPath, 2>* hands) {
  XrActionCreateInfo info{XR_TYPE_ACTION_CREATE_INFO};
  std::strncpy(info.actionName, name, XR_MAX_ACTION_NAME_SIZE - 1);
  std::strncpy(info.localizedActionName, localized, XR_MAX_LOCALIZED_ACTION_NAME_SIZE - 1);
  info.actionType = type;
  if (hands) {
    info.countSubactionPaths = 2;
    info.subactionPaths = hands->data();
  }
  XrAction action = XR_NULL_HANDLE;
  check(xrCreateAction(set, &info, &action), "xrCreateAction");
  return action;
}

RigidPose to_pose(const XrPosef& p) {
  RigidPose out;
  out.position = {p.position.x, p.position.y, p.position.z};
  out.orientation = Quat(p.orientation.w, p.orientation.x, p.orientation.y, p.orientation.z).normalized();
  return out;
}

bool locate(XrSpace space, XrSpace base, XrTime time, RigidPose& pose) {
  XrSpaceLocation loc{XR_TYPE_SPACE_LOCATION};
  if (XR_FAILED(xrLocateSpace(space, base, time, &loc))) return false;
  const XrSpaceLocationFlags need = XR_SPACE_LOCATION_POSITION_VALID_BIT | XR_SPACE_LOCATION_ORIENTATION_VALID_BIT;
  if ((loc.locationFlags & need) != need) return false;
  pose = to_pose(loc.pose);
  return pose.position.allFinite() && pose.orientation.coeffs().allFinite();
}

}  // namespace

ControllerActions::ControllerActions(XrInstance instance, const InputSettings& settings)
    : instance_(instance), settings_(settings) {
  XrActionSetCreateInfo info{XR_TYPE_ACTION_SET_CREATE_INFO};
  std::strcpy(info.actionSetName, "sketchlab");
  std::strcpy(info.localizedActionSetName, "sketchlab drawing");
  check(xrCreateActionSet(instance, &info, &set_), "xrCreateActionSet");
  hand_paths_ = {path_of(instance, "/user/hand/left"), path_of(instance, "/user/hand/right")};
  draw_ = make_action(set_, "draw", "Draw", XR_ACTION_TYPE_FLOAT_INPUT, nullptr);
  grab_ = make_action(set_, "grab", "Grab and zoom", XR_ACTION_TYPE_BOOLEAN_INPUT, &hand_paths_);
  pose_ = make_action(set_, "hand_pose", "Hand pose", XR_ACTION_TYPE_POSE_INPUT, &hand_paths_);
  std::map<std::string, XrAction> by_name{{"draw", draw_}, {"grab", grab_}, {"hand_pose", pose_}};
  for (std::size_t i = 0; i < command_count; ++i) {
    const std::string name(to_string(static_cast<Command>(i)));
    commands_[i] = make_action(set_, name.c_str(), name.c_str(), XR_ACTION_TYPE_BOOLEAN_INPUT, nullptr);
    by_name[name] = commands_[i];
  }
  for (const ProfileBindings& profile : suggested_bindings(settings)) {
    std::vector<XrActionSuggestedBinding> list;
    for (const Binding& b : profile.bindings) list.push_back({by_name.at(b.action), path_of(instance, b.path)});
    XrInteractionProfileSuggestedBinding suggested{XR_TYPE_INTERACTION_PROFILE_SUGGESTED_BINDING};
    suggested.interactionProfile = path_of(instance, profile.profile);
    suggested.countSuggestedBindings = static_cast<uint32_t>(list.size());
    suggested.suggestedBindings = list.data();
    if (const XrResult r = xrSuggestInteractionProfileBindings(instance, &suggested); XR_FAILED(r))
      std::cerr << "sketchlab: warning: the OpenXR runtime refused the bindings for " << profile.profile << " ("
                << result_name(r) << ")\n";
  }
}

ControllerActions::~ControllerActions() {
  for (XrSpace s : hand_spaces_)
    if (s != XR_NULL_HANDLE) xrDestroySpace(s);
  if (set_ != XR_NULL_HANDLE) xrDestroyActionSet(set_);
}

void ControllerActions::attach(XrSession session) {
  XrSessionActionSetsAttachInfo attach{XR_TYPE_SESSION_ACTION_SETS_ATTACH_INFO};
  attach.countActionSets = 1;
  attach.actionSets = &set_;
  check(xrAttachSessionActionSets(session, &attach), "xrAttachSessionActionSets");
  for (int h = 0; h < 2; ++h) {
    XrActionSpaceCreateInfo info{XR_TYPE_ACTION_SPACE_CREATE_INFO};
    info.action = pose_;
    info.subactionPath = hand_paths_[h];
    info.poseInActionSpace.orientation.w = 1.0f;
    check(xrCreateActionSpace(session, &info, &hand_spaces_[h]), "xrCreateActionSpace");
  }
}

ControllerFrame ControllerActions::poll(XrSession session, XrSpace base, XrSpace view_space, XrTime time,
                                        double seconds, bool focused) {
  ControllerFrame frame;
  frame.time = seconds;
  frame.focused = focused;
  frame.head_tracked = locate(view_space, base, time, frame.head);
  if (!focused) return frame;
  XrActiveActionSet active{set_, XR_NULL_PATH};
  XrActionsSyncInfo sync{XR_TYPE_ACTIONS_SYNC_INFO};
  sync.countActiveActionSets = 1;
  sync.activeActionSets = &active;
  const XrResult r = xrSyncActions(session, &sync);
  check(r, "xrSyncActions");
  if (r == XR_SESSION_NOT_FOCUSED) {
    frame.focused = false;
    return frame;
  }
  XrActionStateGetInfo get{XR_TYPE_ACTION_STATE_GET_INFO};
  get.action = draw_;
  XrActionStateFloat draw{XR_TYPE_ACTION_STATE_FLOAT};
  check(xrGetActionStateFloat(session, &get, &draw), "xrGetActionStateFloat");
  frame.draw_value = draw.isActive ? draw.currentState : 0.0;
  for (int h = 0; h < 2; ++h) {
    get.action = grab_;
    get.subactionPath = hand_paths_[h];
    XrActionStateBoolean grab{XR_TYPE_ACTION_STATE_BOOLEAN};
    check(xrGetActionStateBoolean(session, &get, &grab), "xrGetActionStateBoolean");
    get.action = pose_;
    XrActionStatePose pose{XR_TYPE_ACTION_STATE_POSE};
    check(xrGetActionStatePose(session, &get, &pose), "xrGetActionStatePose");
    frame.hands[h].grab = grab.isActive && grab.currentState;
    frame.hands[h].tracked = pose.isActive && locate(hand_spaces_[h], base, time, frame.hands[h].aim);
  }
  get.subactionPath = XR_NULL_PATH;
  for (std::size_t i = 0; i < command_count; ++i) {
    get.action = commands_[i];
    XrActionStateBoolean b{XR_TYPE_ACTION_STATE_BOOLEAN};
    check(xrGetActionStateBoolean(session, &get, &b), "xrGetActionStateBoolean");
    frame.buttons[i] = b.isActive && b.currentState;
  }
  return frame;
}

std::string ControllerActions::current_profile(XrSession session) const {
  XrInteractionProfileState state{XR_TYPE_INTERACTION_PROFILE_STATE};
  if (XR_FAILED(xrGetCurrentInteractionProfile(session, hand_paths_[static_cast<int>(settings_.dominant)], &state)) ||
      state.interactionProfile == XR_NULL_PATH)
    return {};
  char buffer[XR_MAX_PATH_LENGTH];
  uint32_t n = 0;
  if (XR_FAILED(xrPathToString(instance_, state.interactionProfile, sizeof buffer, &n, buffer))) return {};
  return buffer;
}

}  // namespace sketchlab::openxr
