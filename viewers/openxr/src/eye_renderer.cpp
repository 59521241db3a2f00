#include "eye_renderer.hpp"

// glew first: it must precede gl.h (pulled in by glx.h); Xlib last, its
// macros (None, Status, ...) would break VTK headers.
#include <vtk_glew.h>

#include <cmath>
#include <stdexcept>

#include <vtkCamera.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkOpenGLState.h>

#include <GL/glx.h>

namespace sketchlab::vr {

Mat4 fov_projection(const EyeFov& fov, double n, double f) {
  const double l = std::tan(fov.left) * n, r = std::tan(fov.right) * n;
  const double t = std::tan(fov.up) * n, b = std::tan(fov.down) * n;
  Mat4 p = Mat4::Zero();
  p(0, 0) = 2 * n / (r - l);
  p(0, 2) = (r + l) / (r - l);
  p(1, 1) = 2 * n / (t - b);
  p(1, 2) = (t + b) / (t - b);
  p(2, 2) = -(f + n) / (f - n);
  p(2, 3) = -2 * f * n / (f - n);
  p(3, 2) = -1;
  return p;
}

EyeRenderer::EyeRenderer(int width, int height) : width_(width), height_(height) {
  if (width <= 0 || height <= 0 || width > 16384 || height > 16384)
    throw std::runtime_error("eye image size " + std::to_string(width) + "x" + std::to_string(height) +
                             " is not usable");
  window_ = vtkSmartPointer<vtkRenderWindow>::New();
  window_->SetOffScreenRendering(1);
  window_->SetMultiSamples(0);
  window_->SetSize(width, height);
  renderer_ = vtkSmartPointer<vtkRenderer>::New();
  window_->AddRenderer(renderer_);
  auto* gl = vtkOpenGLRenderWindow::SafeDownCast(window_);
  if (!gl) throw std::runtime_error("VTK's render window is not an OpenGL window");
  // The result stays in VTK's framebuffer; render() blits it where it goes.
  gl->SetFrameBlitModeToNoBlit();
  gl->Initialize();
  window_->MakeCurrent();
  if (!window_->GetGenericContext() || !glXGetCurrentContext())
    throw std::runtime_error("VTK could not create an OpenGL (GLX) context on this display");
  glGenFramebuffers(1, &fbo_);
}

EyeRenderer::~EyeRenderer() {
  if (fbo_) {
    window_->MakeCurrent();
    glDeleteFramebuffers(1, &fbo_);
  }
  window_->Finalize();
}

void EyeRenderer::make_current() { window_->MakeCurrent(); }

GlxHandles EyeRenderer::glx_handles() {
  make_current();
  GlxHandles h;
  auto* display = static_cast<Display*>(window_->GetGenericDisplayId());
  const GLXContext context = glXGetCurrentContext();
  h.display = display;
  h.context = context;
  h.drawable = glXGetCurrentDrawable();
  int id = 0;
  if (glXQueryContext(display, context, GLX_FBCONFIG_ID, &id) != Success)
    throw std::runtime_error("cannot query the GLX framebuffer configuration of VTK's context");
  const int attributes[] = {GLX_FBCONFIG_ID, id, None};
  int count = 0;
  GLXFBConfig* configs = glXChooseFBConfig(display, DefaultScreen(display), attributes, &count);
  if (!configs || count < 1) throw std::runtime_error("cannot find the GLX framebuffer configuration of VTK's context");
  h.fbconfig = configs[0];
  if (XVisualInfo* visual = glXGetVisualFromFBConfig(display, configs[0])) {
    h.visualid = static_cast<std::uint32_t>(visual->visualid);
    XFree(visual);
  }
  XFree(configs);
  return h;
}

void EyeRenderer::render(const Vec3& position, const Quat& orientation, const EyeFov& fov, std::uint32_t texture,
                         double near_clip, double far_clip) {
  vtkCamera* camera = renderer_->GetActiveCamera();
  const Vec3 forward = orientation * Vec3(0, 0, -1), up = orientation * Vec3(0, 1, 0);
  const Vec3 focal = position + forward;
  camera->SetPosition(position.x(), position.y(), position.z());
  camera->SetFocalPoint(focal.x(), focal.y(), focal.z());
  camera->SetViewUp(up.x(), up.y(), up.z());
  camera->SetClippingRange(near_clip, far_clip);
  const Mat4 p = fov_projection(fov, near_clip, far_clip);
  vtkNew<vtkMatrix4x4> projection;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) projection->SetElement(r, c, p(r, c));
  camera->SetExplicitProjectionTransformMatrix(projection);
  camera->UseExplicitProjectionTransformMatrixOn();
  window_->Render();

  auto* gl = vtkOpenGLRenderWindow::SafeDownCast(window_);
  vtkOpenGLState* state = gl->GetState();
  state->PushFramebufferBindings();
  state->vtkglBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo_);
  glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture, 0);
  const GLenum draw = GL_COLOR_ATTACHMENT0;
  glDrawBuffers(1, &draw);
  gl->BlitDisplayFramebuffer();
  glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, 0, 0);
  state->PopFramebufferBindings();
}

}  // namespace sketchlab::vr
