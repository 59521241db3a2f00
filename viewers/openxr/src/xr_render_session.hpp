#pragma once
// The OpenXR side of the VR viewer: instance with XR_KHR_opengl_enable,
// the head-mounted system, a session on VTK's GLX context, stage (or
// local) and view spaces, one swapchain per eye, and the session state
// machine (OpenXR 1.0 §9.3: begin on READY, end on STOPPING, leave on
// EXITING / LOSS_PENDING / instance loss).
//
// Every failure is an XrError whose message says what is missing and how
// to fix it (no runtime: set XR_RUNTIME_JSON; no headset; extension
// missing; session refused).
#include <openxr/openxr.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "eye_renderer.hpp"

namespace sketchlab::vr {

struct EyeView {
  Vec3 position = Vec3::Zero();
  Quat orientation = Quat::Identity();
  EyeFov fov;
};

class XrRenderSession {
 public:
  // Instance and system; throws openxr::XrError.
  XrRenderSession();
  ~XrRenderSession();
  XrRenderSession(const XrRenderSession&) = delete;
  XrRenderSession& operator=(const XrRenderSession&) = delete;

  // Recommended eye image size.
  int eye_width() const { return eye_width_; }
  int eye_height() const { return eye_height_; }
  const std::string& runtime_name() const { return runtime_name_; }
  XrInstance instance() const { return instance_; }

  // Creates the session on `gl` (current on this thread), the spaces and the
  // swapchains. Throws openxr::XrError.
  void start(const GlxHandles& gl);
  XrSession session() const { return session_; }
  XrSpace base_space() const { return base_; }
  XrSpace view_space() const { return view_; }

  // Handles pending runtime events. Returns false once the application must
  // leave (session exited or lost, instance lost); `lost` tells which.
  bool poll(bool& lost);
  bool running() const { return running_; }
  bool focused() const { return state_ == XR_SESSION_STATE_FOCUSED; }
  XrSessionState state() const { return state_; }
  void request_exit();

  // One frame: waits, begins, renders each eye with `draw` (eye index,
  // view, GL texture) when the runtime wants pixels, ends. `before_render`
  // runs after the wait with the predicted display time (input polling).
  template <class Before, class Draw>
  void frame(Before&& before_render, Draw&& draw);

 private:
  XrFrameState wait_and_begin();
  bool locate_views(XrTime time, std::array<EyeView, 2>& views, std::array<XrView, 2>& raw);
  std::uint32_t acquire(int eye);
  void release(int eye);
  void end(XrTime time, const std::array<XrView, 2>* views);

  XrInstance instance_ = XR_NULL_HANDLE;
  XrSystemId system_ = XR_NULL_SYSTEM_ID;
  XrSession session_ = XR_NULL_HANDLE;
  XrSpace base_ = XR_NULL_HANDLE, view_ = XR_NULL_HANDLE;
  std::array<XrSwapchain, 2> swapchains_{XR_NULL_HANDLE, XR_NULL_HANDLE};
  std::array<std::vector<std::uint32_t>, 2> images_;
  int eye_width_ = 0, eye_height_ = 0;
  std::string runtime_name_;
  XrSessionState state_ = XR_SESSION_STATE_UNKNOWN;
  bool running_ = false, exit_requested_ = false;
};

template <class Before, class Draw>
void XrRenderSession::frame(Before&& before_render, Draw&& draw) {
  const XrFrameState fs = wait_and_begin();
  before_render(fs.predictedDisplayTime);
  std::array<EyeView, 2> views;
  std::array<XrView, 2> raw;
  const bool render = fs.shouldRender && locate_views(fs.predictedDisplayTime, views, raw);
  if (render)
    for (int eye = 0; eye < 2; ++eye) {
      const std::uint32_t texture = acquire(eye);
      draw(eye, views[static_cast<std::size_t>(eye)], texture);
      release(eye);
    }
  end(fs.predictedDisplayTime, render ? &raw : nullptr);
}

}  // namespace sketchlab::vr
