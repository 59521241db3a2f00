#include "headless_session.hpp"

#include <dlfcn.h>
#include <time.h>
#define XR_USE_TIMESPEC
#include <openxr/openxr_platform.h>

#include <algorithm>
#include <cstring>
#include <thread>
#include <vector>

#include "xr_result.hpp"
#include "xr_session_basics.hpp"

namespace sketchlab::openxr {
namespace {

constexpr const char* no_runtime_hint =
    "no OpenXR runtime is available: install one (Monado, SteamVR) and make it active, or set "
    "XR_RUNTIME_JSON to its runtime manifest (e.g. /usr/share/openxr/1/openxr_monado.json)";

bool offers(const char* extension) {
  uint32_t n = 0;
  if (XR_FAILED(xrEnumerateInstanceExtensionProperties(nullptr, 0, &n, nullptr))) return false;
  std::vector<XrExtensionProperties> props(n, {XR_TYPE_EXTENSION_PROPERTIES});
  if (XR_FAILED(xrEnumerateInstanceExtensionProperties(nullptr, n, &n, props.data()))) return false;
  for (const auto& p : props)
    if (std::strcmp(p.extensionName, extension) == 0) return true;
  return false;
}

}  // namespace

HeadlessSession::HeadlessSession(const InputSettings& settings, const Workspace& workspace)
    : interpreter_(settings, workspace) {
#ifdef SKETCHLAB_SANITIZED
  // Keeps Debian's OpenXR loader mapped after the plugin is unloaded, so that
  // LeakSanitizer at exit names it in the stacks of the instance record its
  // xrDestroyInstance never frees (suppressed in tests/lsan.supp); unmapped,
  // those frames are "<unknown module>", which no suppression can match.
  dlopen("libopenxr_loader.so.1", RTLD_LAZY | RTLD_NOLOAD | RTLD_NODELETE);
#endif
  uint32_t n = 0;
  if (const XrResult r = xrEnumerateInstanceExtensionProperties(nullptr, 0, &n, nullptr); XR_FAILED(r))
    throw XrError(r, std::string(no_runtime_hint) + " (" + result_name(r) + ")");
  if (!offers(XR_MND_HEADLESS_EXTENSION_NAME))
    throw XrError(XR_ERROR_EXTENSION_NOT_PRESENT,
                  "the OpenXR runtime lacks XR_MND_headless, which the openxr input needs on its own; "
                  "draw with `sketchlab vr CONFIG` instead (it reads the controllers in its session)");
  std::vector<const char*> extensions{XR_MND_HEADLESS_EXTENSION_NAME};
  const bool clock = offers(XR_KHR_CONVERT_TIMESPEC_TIME_EXTENSION_NAME);
  if (clock) extensions.push_back(XR_KHR_CONVERT_TIMESPEC_TIME_EXTENSION_NAME);
  XrInstanceCreateInfo info{XR_TYPE_INSTANCE_CREATE_INFO};
  std::strcpy(info.applicationInfo.applicationName, "sketchlab input");
  info.applicationInfo.apiVersion = XR_CURRENT_API_VERSION;
  info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
  info.enabledExtensionNames = extensions.data();
  if (const XrResult r = xrCreateInstance(&info, &instance_); XR_FAILED(r))
    throw XrError(r, std::string(no_runtime_hint) + " (xrCreateInstance: " + result_name(r) + ")");
  poll_period_ = std::chrono::duration_cast<std::chrono::steady_clock::duration>(
      std::chrono::duration<double>(1.0 / settings.headless_poll_hz));
  try {
    if (clock)
      check(xrGetInstanceProcAddr(instance_, "xrConvertTimespecTimeToTimeKHR", &convert_time_),
            "xrGetInstanceProcAddr(xrConvertTimespecTimeToTimeKHR)");
    if (const XrResult r = find_headset(instance_, runtime_name_, system_); XR_FAILED(r))
      throw XrError(r, "OpenXR runtime '" + runtime_name_ + "' has no headset (" + result_name(r) +
                           "): connect and switch on the headset");
    actions_ = std::make_unique<ControllerActions>(instance_, settings);
    XrSessionCreateInfo sci{XR_TYPE_SESSION_CREATE_INFO};
    sci.systemId = system_;
    if (const XrResult r = xrCreateSession(instance_, &sci, &session_); XR_FAILED(r))
      throw XrError(r, "OpenXR runtime '" + runtime_name_ + "' refused the session (" + result_name(r) +
                           "): close other VR applications and check the headset");
    actions_->attach(session_);
    create_reference_spaces(session_, base_, view_);
  } catch (...) {
    actions_.reset();
    if (session_ != XR_NULL_HANDLE) xrDestroySession(session_);
    xrDestroyInstance(instance_);
    throw;
  }
}

HeadlessSession::~HeadlessSession() {
  actions_.reset();
  if (base_ != XR_NULL_HANDLE) xrDestroySpace(base_);
  if (view_ != XR_NULL_HANDLE) xrDestroySpace(view_);
  if (session_ != XR_NULL_HANDLE) xrDestroySession(session_);
  if (instance_ != XR_NULL_HANDLE) xrDestroyInstance(instance_);
}

bool HeadlessSession::poll_state() {
  XrEventDataBuffer event{XR_TYPE_EVENT_DATA_BUFFER};
  while (xrPollEvent(instance_, &event) == XR_SUCCESS) {
    if (event.type == XR_TYPE_EVENT_DATA_INSTANCE_LOSS_PENDING) return false;
    if (event.type == XR_TYPE_EVENT_DATA_SESSION_STATE_CHANGED) {
      state_ = reinterpret_cast<const XrEventDataSessionStateChanged&>(event).state;
      if (!follow_session_state(session_, state_, running_)) return false;
    }
    event = {XR_TYPE_EVENT_DATA_BUFFER};
  }
  return true;
}

XrTime HeadlessSession::runtime_now() const {
  timespec now{};
  clock_gettime(CLOCK_MONOTONIC, &now);
  XrTime time = 0;
  check(reinterpret_cast<PFN_xrConvertTimespecTimeToTimeKHR>(convert_time_)(instance_, &now, &time),
        "xrConvertTimespecTimeToTimeKHR");
  return time;
}

std::vector<Event> HeadlessSession::poll_controllers(XrTime time) {
  if (start_ == 0) start_ = time;
  const double seconds = static_cast<double>(time - start_) * 1e-9;
  last_seconds_ = seconds;
  return interpreter_.step(
      actions_->poll(session_, base_, view_, time, seconds, state_ == XR_SESSION_STATE_FOCUSED));
}

void HeadlessSession::request_exit() {
  if (running_) check(xrRequestExitSession(session_), "xrRequestExitSession");
}

std::vector<Event> HeadlessSession::next_events(std::chrono::milliseconds wait) {
  using Clock = std::chrono::steady_clock;
  const auto until = Clock::now() + wait;
  while (!ended_) {
    if (!poll_state()) {
      ended_ = true;
      // The stroke in progress and an unfinished zoom are kept.
      ControllerFrame last;
      last.focused = false;
      last.time = last_seconds_;
      return interpreter_.step(last);
    }
    std::vector<Event> events;
    if (!running_) {
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    } else if (convert_time_) {
      // No frame functions: paced here, timed by the runtime's clock.
      const auto now = Clock::now();
      if (next_poll_ > now) std::this_thread::sleep_until(next_poll_);
      next_poll_ = std::max(next_poll_, now) + poll_period_;
      events = poll_controllers(runtime_now());
    } else {
      XrFrameState fs{XR_TYPE_FRAME_STATE};
      check(xrWaitFrame(session_, nullptr, &fs), "xrWaitFrame");
      check(xrBeginFrame(session_, nullptr), "xrBeginFrame");
      events = poll_controllers(fs.predictedDisplayTime);
      XrFrameEndInfo end{XR_TYPE_FRAME_END_INFO};
      end.displayTime = fs.predictedDisplayTime;
      end.environmentBlendMode = XR_ENVIRONMENT_BLEND_MODE_OPAQUE;
      check(xrEndFrame(session_, &end), "xrEndFrame");
    }
    if (!events.empty() || Clock::now() >= until) return events;
  }
  return {};
}

}  // namespace sketchlab::openxr
