#pragma once
// VTK rendering of one scene into OpenXR swapchain images.
//
// The robust path on Debian's VTK 9.1 (no OpenXR module): VTK owns the GL
// context (an offscreen X render window, which works on any GLX driver and
// under Xvfb) and that same context is given to the OpenXR session
// (XrGraphicsBindingOpenGLXlibKHR), so swapchain textures live in it. Each
// eye is rendered by VTK into its own framebuffer, then blitted on the GPU
// into the swapchain texture (BlitDisplayFramebuffer into an FBO holding
// the texture): no second context, no sharing, no copy through the CPU.
#include <cstdint>

#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

#include "sketchlab/types.hpp"

namespace sketchlab::vr {

// What XrGraphicsBindingOpenGLXlibKHR needs (Xlib/GLX types kept opaque).
struct GlxHandles {
  void* display = nullptr;      // Display*
  std::uint32_t visualid = 0;
  void* fbconfig = nullptr;     // GLXFBConfig
  unsigned long drawable = 0;   // GLXDrawable
  void* context = nullptr;      // GLXContext
};

// Field of view of one eye: tangent-space angles in radians (OpenXR XrFovf).
struct EyeFov {
  double left = -0.7, right = 0.7, up = 0.6, down = -0.6;
};

class EyeRenderer {
 public:
  // Creates the offscreen window and its GL context (width x height pixels
  // per eye). Throws std::runtime_error when no context can be made.
  EyeRenderer(int width, int height);
  ~EyeRenderer();
  EyeRenderer(const EyeRenderer&) = delete;
  EyeRenderer& operator=(const EyeRenderer&) = delete;

  // Makes the context current on this thread and returns its handles.
  GlxHandles glx_handles();
  void make_current();
  vtkRenderer* renderer() { return renderer_; }

  // Renders the scene seen from `eye` (stage pose: position, orientation;
  // camera looks down -z, y up) with `fov` into GL texture `texture`
  // (GL_TEXTURE_2D of this renderer's size), clipping at [near, far] m.
  void render(const Vec3& position, const Quat& orientation, const EyeFov& fov, std::uint32_t texture,
              double near_clip = 0.02, double far_clip = 100.0);

  int width() const { return width_; }
  int height() const { return height_; }

 private:
  int width_, height_;
  vtkSmartPointer<vtkRenderWindow> window_;
  vtkSmartPointer<vtkRenderer> renderer_;
  std::uint32_t fbo_ = 0;
};

// The OpenGL projection matrix of an asymmetric frustum (OpenXR fov angles).
Mat4 fov_projection(const EyeFov& fov, double near_clip, double far_clip);

}  // namespace sketchlab::vr
