#pragma once
// The session plumbing that the openxr input's headless session and the VR
// viewer's rendering session do alike, so both follow the runtime the same
// way. Needs a live XrSession; errors are thrown as XrError (xr_result.hpp).
#include <openxr/openxr.h>

#include <string>

namespace sketchlab::openxr {

// Reads the runtime's name into `runtime_name` (left as it is when the
// runtime does not say) and looks up the head-mounted system into `system`.
// Returns xrGetSystem's result, so the caller says in its own words what a
// missing headset means for it.
XrResult find_headset(XrInstance instance, std::string& runtime_name, XrSystemId& system);

// Creates `base`, the space poses are read in (STAGE; LOCAL where the runtime
// has no stage, as in seated setups without a play area), and `view`, the
// headset's own space. Throws when neither STAGE nor LOCAL nor VIEW can be made.
void create_reference_spaces(XrSession session, XrSpace& base, XrSpace& view);

// Acts on a session state change as OpenXR requires: begins the session
// (primary stereo) on READY and ends it on STOPPING, updating `running`.
// Returns false when the session is over (EXITING or LOSS_PENDING): the
// caller stops polling and tears down; true otherwise.
bool follow_session_state(XrSession session, XrSessionState state, bool& running);

}  // namespace sketchlab::openxr
