#include "xr_render_session.hpp"

#include <X11/Xlib.h>
#include <GL/glx.h>
#define XR_USE_GRAPHICS_API_OPENGL
#define XR_USE_PLATFORM_XLIB
#include <openxr/openxr_platform.h>

#include <cstring>
#include <iostream>

#include "xr_result.hpp"
#include "xr_session_basics.hpp"

namespace sketchlab::vr {

using openxr::check;
using openxr::result_name;
using openxr::XrError;

namespace {

constexpr const char* runtime_hint =
    "install an OpenXR runtime (Monado, or SteamVR) and make it the active one, or point "
    "XR_RUNTIME_JSON at its runtime manifest, e.g. XR_RUNTIME_JSON=/usr/share/openxr/1/openxr_monado.json "
    "(see README.md, \"VR\")";

std::vector<std::string> offered_extensions() {
  uint32_t n = 0;
  if (const XrResult r = xrEnumerateInstanceExtensionProperties(nullptr, 0, &n, nullptr); XR_FAILED(r))
    throw XrError(r, std::string("no OpenXR runtime found (") + result_name(r) + "): " + runtime_hint);
  std::vector<XrExtensionProperties> props(n, {XR_TYPE_EXTENSION_PROPERTIES});
  check(xrEnumerateInstanceExtensionProperties(nullptr, n, &n, props.data()),
        "xrEnumerateInstanceExtensionProperties");
  std::vector<std::string> names;
  for (const auto& p : props) names.emplace_back(p.extensionName);
  return names;
}

}  // namespace

XrRenderSession::XrRenderSession() {
  const auto extensions = offered_extensions();
  bool gl = false;
  for (const auto& e : extensions) gl = gl || e == XR_KHR_OPENGL_ENABLE_EXTENSION_NAME;
  if (!gl)
    throw XrError(XR_ERROR_EXTENSION_NOT_PRESENT,
                  "the active OpenXR runtime does not offer " XR_KHR_OPENGL_ENABLE_EXTENSION_NAME
                  ", which the VR viewer renders with: use a runtime with OpenGL support (Monado, SteamVR) "
                  "or point XR_RUNTIME_JSON at one");
  const char* enabled[] = {XR_KHR_OPENGL_ENABLE_EXTENSION_NAME};
  XrInstanceCreateInfo info{XR_TYPE_INSTANCE_CREATE_INFO};
  std::strcpy(info.applicationInfo.applicationName, "sketchlab");
  info.applicationInfo.applicationVersion = 1;
  std::strcpy(info.applicationInfo.engineName, "VTK");
  info.applicationInfo.apiVersion = XR_CURRENT_API_VERSION;
  info.enabledExtensionCount = 1;
  info.enabledExtensionNames = enabled;
  if (const XrResult r = xrCreateInstance(&info, &instance_); XR_FAILED(r))
    throw XrError(r, std::string("the OpenXR runtime failed to start (xrCreateInstance: ") + result_name(r) +
                         "): " + runtime_hint);
  try {
    if (const XrResult r = openxr::find_headset(instance_, runtime_name_, system_); XR_FAILED(r))
      throw XrError(r, "the OpenXR runtime '" + runtime_name_ + "' reports no headset (" + result_name(r) +
                           "): connect and switch on the headset (and start the runtime's service, e.g. "
                           "monado-service or SteamVR)");
    uint32_t n = 0;
    check(xrEnumerateViewConfigurationViews(instance_, system_, XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO, 0, &n,
                                            nullptr),
          "xrEnumerateViewConfigurationViews");
    if (n != 2)
      throw XrError(XR_ERROR_VIEW_CONFIGURATION_TYPE_UNSUPPORTED,
                    "the headset has " + std::to_string(n) + " views; the VR viewer needs a stereo headset");
    std::vector<XrViewConfigurationView> views(n, {XR_TYPE_VIEW_CONFIGURATION_VIEW});
    check(xrEnumerateViewConfigurationViews(instance_, system_, XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO, n, &n,
                                            views.data()),
          "xrEnumerateViewConfigurationViews");
    eye_width_ = static_cast<int>(views[0].recommendedImageRectWidth);
    eye_height_ = static_cast<int>(views[0].recommendedImageRectHeight);
  } catch (...) {
    xrDestroyInstance(instance_);
    throw;
  }
}

XrRenderSession::~XrRenderSession() {
  for (XrSwapchain s : swapchains_)
    if (s != XR_NULL_HANDLE) xrDestroySwapchain(s);
  if (base_ != XR_NULL_HANDLE) xrDestroySpace(base_);
  if (view_ != XR_NULL_HANDLE) xrDestroySpace(view_);
  if (session_ != XR_NULL_HANDLE) xrDestroySession(session_);
  if (instance_ != XR_NULL_HANDLE) xrDestroyInstance(instance_);
}

void XrRenderSession::start(const GlxHandles& gl) {
  PFN_xrGetOpenGLGraphicsRequirementsKHR requirements = nullptr;
  check(xrGetInstanceProcAddr(instance_, "xrGetOpenGLGraphicsRequirementsKHR",
                              reinterpret_cast<PFN_xrVoidFunction*>(&requirements)),
        "xrGetInstanceProcAddr(xrGetOpenGLGraphicsRequirementsKHR)");
  XrGraphicsRequirementsOpenGLKHR needs{XR_TYPE_GRAPHICS_REQUIREMENTS_OPENGL_KHR};
  check(requirements(instance_, system_, &needs), "xrGetOpenGLGraphicsRequirementsKHR");

  XrGraphicsBindingOpenGLXlibKHR binding{XR_TYPE_GRAPHICS_BINDING_OPENGL_XLIB_KHR};
  binding.xDisplay = static_cast<Display*>(gl.display);
  binding.visualid = gl.visualid;
  binding.glxFBConfig = static_cast<GLXFBConfig>(gl.fbconfig);
  binding.glxDrawable = gl.drawable;
  binding.glxContext = static_cast<GLXContext>(gl.context);
  XrSessionCreateInfo info{XR_TYPE_SESSION_CREATE_INFO};
  info.next = &binding;
  info.systemId = system_;
  if (const XrResult r = xrCreateSession(instance_, &info, &session_); XR_FAILED(r))
    throw XrError(r, "the OpenXR runtime '" + runtime_name_ + "' refused the session (" + result_name(r) +
                         "): close other VR applications, check that the headset is connected and awake, "
                         "and that the runtime supports OpenGL on X11");

  openxr::create_reference_spaces(session_, base_, view_);

  uint32_t n = 0;
  check(xrEnumerateSwapchainFormats(session_, 0, &n, nullptr), "xrEnumerateSwapchainFormats");
  std::vector<int64_t> formats(n);
  check(xrEnumerateSwapchainFormats(session_, n, &n, formats.data()), "xrEnumerateSwapchainFormats");
  // Linear RGBA8 keeps VTK's colours as they are; sRGB otherwise.
  int64_t format = 0;
  for (int64_t wanted : {int64_t{0x8058} /* GL_RGBA8 */, int64_t{0x8C43} /* GL_SRGB8_ALPHA8 */})
    for (int64_t f : formats)
      if (!format && f == wanted) format = f;
  if (!format)
    throw XrError(XR_ERROR_SWAPCHAIN_FORMAT_UNSUPPORTED,
                  "the OpenXR runtime offers neither GL_RGBA8 nor GL_SRGB8_ALPHA8 swapchains");
  for (int eye = 0; eye < 2; ++eye) {
    XrSwapchainCreateInfo sci{XR_TYPE_SWAPCHAIN_CREATE_INFO};
    sci.usageFlags = XR_SWAPCHAIN_USAGE_COLOR_ATTACHMENT_BIT | XR_SWAPCHAIN_USAGE_TRANSFER_DST_BIT;
    sci.format = format;
    sci.sampleCount = 1;
    sci.width = static_cast<uint32_t>(eye_width_);
    sci.height = static_cast<uint32_t>(eye_height_);
    sci.faceCount = 1;
    sci.arraySize = 1;
    sci.mipCount = 1;
    check(xrCreateSwapchain(session_, &sci, &swapchains_[eye]), "xrCreateSwapchain");
    uint32_t count = 0;
    check(xrEnumerateSwapchainImages(swapchains_[eye], 0, &count, nullptr), "xrEnumerateSwapchainImages");
    std::vector<XrSwapchainImageOpenGLKHR> images(count, {XR_TYPE_SWAPCHAIN_IMAGE_OPENGL_KHR});
    check(xrEnumerateSwapchainImages(swapchains_[eye], count, &count,
                                     reinterpret_cast<XrSwapchainImageBaseHeader*>(images.data())),
          "xrEnumerateSwapchainImages");
    for (const auto& image : images) images_[eye].push_back(image.image);
  }
}

bool XrRenderSession::poll(bool& lost) {
  lost = false;
  XrEventDataBuffer event{XR_TYPE_EVENT_DATA_BUFFER};
  while (xrPollEvent(instance_, &event) == XR_SUCCESS) {
    switch (event.type) {
      case XR_TYPE_EVENT_DATA_INSTANCE_LOSS_PENDING:
        lost = true;
        return false;
      case XR_TYPE_EVENT_DATA_SESSION_STATE_CHANGED: {
        state_ = reinterpret_cast<const XrEventDataSessionStateChanged&>(event).state;
        if (!openxr::follow_session_state(session_, state_, running_)) {
          lost = state_ == XR_SESSION_STATE_LOSS_PENDING;
          return false;
        }
        break;
      }
      default:
        break;
    }
    event = {XR_TYPE_EVENT_DATA_BUFFER};
  }
  return true;
}

void XrRenderSession::request_exit() {
  if (exit_requested_) return;
  exit_requested_ = true;
  if (running_) xrRequestExitSession(session_);
}

XrFrameState XrRenderSession::wait_and_begin() {
  XrFrameState fs{XR_TYPE_FRAME_STATE};
  check(xrWaitFrame(session_, nullptr, &fs), "xrWaitFrame");
  check(xrBeginFrame(session_, nullptr), "xrBeginFrame");
  return fs;
}

bool XrRenderSession::locate_views(XrTime time, std::array<EyeView, 2>& views, std::array<XrView, 2>& raw) {
  XrViewLocateInfo info{XR_TYPE_VIEW_LOCATE_INFO};
  info.viewConfigurationType = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
  info.displayTime = time;
  info.space = base_;
  XrViewState state{XR_TYPE_VIEW_STATE};
  uint32_t n = 0;
  raw.fill({XR_TYPE_VIEW});
  if (XR_FAILED(xrLocateViews(session_, &info, &state, 2, &n, raw.data())) || n != 2) return false;
  const XrViewStateFlags need = XR_VIEW_STATE_POSITION_VALID_BIT | XR_VIEW_STATE_ORIENTATION_VALID_BIT;
  if ((state.viewStateFlags & need) != need) return false;
  for (int i = 0; i < 2; ++i) {
    const XrView& v = raw[static_cast<std::size_t>(i)];
    EyeView& e = views[static_cast<std::size_t>(i)];
    e.position = {v.pose.position.x, v.pose.position.y, v.pose.position.z};
    e.orientation = Quat(v.pose.orientation.w, v.pose.orientation.x, v.pose.orientation.y, v.pose.orientation.z)
                        .normalized();
    e.fov = {v.fov.angleLeft, v.fov.angleRight, v.fov.angleUp, v.fov.angleDown};
    if (!e.position.allFinite() || !e.orientation.coeffs().allFinite()) return false;
  }
  return true;
}

std::uint32_t XrRenderSession::acquire(int eye) {
  uint32_t index = 0;
  check(xrAcquireSwapchainImage(swapchains_[eye], nullptr, &index), "xrAcquireSwapchainImage");
  XrSwapchainImageWaitInfo wait{XR_TYPE_SWAPCHAIN_IMAGE_WAIT_INFO};
  wait.timeout = XR_INFINITE_DURATION;
  check(xrWaitSwapchainImage(swapchains_[eye], &wait), "xrWaitSwapchainImage");
  return images_[eye].at(index);
}

void XrRenderSession::release(int eye) {
  check(xrReleaseSwapchainImage(swapchains_[eye], nullptr), "xrReleaseSwapchainImage");
}

void XrRenderSession::end(XrTime time, const std::array<XrView, 2>* views) {
  std::array<XrCompositionLayerProjectionView, 2> projection{};
  XrCompositionLayerProjection layer{XR_TYPE_COMPOSITION_LAYER_PROJECTION};
  const XrCompositionLayerBaseHeader* layers[] = {reinterpret_cast<const XrCompositionLayerBaseHeader*>(&layer)};
  XrFrameEndInfo end{XR_TYPE_FRAME_END_INFO};
  end.displayTime = time;
  end.environmentBlendMode = XR_ENVIRONMENT_BLEND_MODE_OPAQUE;
  if (views) {
    for (int eye = 0; eye < 2; ++eye) {
      auto& p = projection[static_cast<std::size_t>(eye)];
      p = {XR_TYPE_COMPOSITION_LAYER_PROJECTION_VIEW};
      p.pose = (*views)[static_cast<std::size_t>(eye)].pose;
      p.fov = (*views)[static_cast<std::size_t>(eye)].fov;
      p.subImage.swapchain = swapchains_[eye];
      p.subImage.imageRect = {{0, 0}, {eye_width_, eye_height_}};
    }
    layer.space = base_;
    layer.viewCount = 2;
    layer.views = projection.data();
    end.layerCount = 1;
    end.layers = layers;
  }
  check(xrEndFrame(session_, &end), "xrEndFrame");
}

}  // namespace sketchlab::vr
