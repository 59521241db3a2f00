#include "xr_session_basics.hpp"

#include "xr_result.hpp"

namespace sketchlab::openxr {

XrResult find_headset(XrInstance instance, std::string& runtime_name, XrSystemId& system) {
  XrInstanceProperties props{XR_TYPE_INSTANCE_PROPERTIES};
  if (XR_SUCCEEDED(xrGetInstanceProperties(instance, &props))) runtime_name = props.runtimeName;
  XrSystemGetInfo sys{XR_TYPE_SYSTEM_GET_INFO};
  sys.formFactor = XR_FORM_FACTOR_HEAD_MOUNTED_DISPLAY;
  return xrGetSystem(instance, &sys, &system);
}

void create_reference_spaces(XrSession session, XrSpace& base, XrSpace& view) {
  XrReferenceSpaceCreateInfo space{XR_TYPE_REFERENCE_SPACE_CREATE_INFO};
  space.poseInReferenceSpace.orientation.w = 1.0f;
  space.referenceSpaceType = XR_REFERENCE_SPACE_TYPE_STAGE;
  if (XR_FAILED(xrCreateReferenceSpace(session, &space, &base))) {
    // Seated setups without a play area have no stage.
    space.referenceSpaceType = XR_REFERENCE_SPACE_TYPE_LOCAL;
    check(xrCreateReferenceSpace(session, &space, &base), "xrCreateReferenceSpace(LOCAL)");
  }
  space.referenceSpaceType = XR_REFERENCE_SPACE_TYPE_VIEW;
  check(xrCreateReferenceSpace(session, &space, &view), "xrCreateReferenceSpace(VIEW)");
}

bool follow_session_state(XrSession session, XrSessionState state, bool& running) {
  if (state == XR_SESSION_STATE_READY) {
    XrSessionBeginInfo begin{XR_TYPE_SESSION_BEGIN_INFO};
    begin.primaryViewConfigurationType = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
    check(xrBeginSession(session, &begin), "xrBeginSession");
    running = true;
  } else if (state == XR_SESSION_STATE_STOPPING) {
    check(xrEndSession(session), "xrEndSession");
    running = false;
  } else if (state == XR_SESSION_STATE_EXITING || state == XR_SESSION_STATE_LOSS_PENDING) {
    return false;
  }
  return true;
}

}  // namespace sketchlab::openxr
