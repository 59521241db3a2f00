#pragma once
// The desktop viewer's window: one viewport per stack with a shared (linked)
// camera, an overlay with the status line, timeline and help, and its own X
// event loop (XInput2 pointer events, core key events) driving the model.
#include <chrono>
#include <memory>
#include <vector>

#include <vtkActor.h>
#include <vtkActor2D.h>
#include <vtkCamera.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTextActor.h>

#include "constraint_markers.hpp"
#include "scene_actors.hpp"
#include "sketchlab/desktop/view_app.hpp"
#include "sketchlab/desktop/viewer_model.hpp"
#include "sketchlab/geometry/plane.hpp"
#include "sketchlab/plugin/pointer_input.hpp"
#include "x_pointer.hpp"

namespace sketchlab::desktop {

// Height of the replay timeline at the bottom of the window, in pixels.
constexpr int timeline_height = 14;

struct WindowOptions {
  ViewOptions options;
};

// The plane strokes are drawn on (the kernel's Plane: a point on it and the
// unit normal), and whether it is shown.
struct DrawPlane {
  Plane plane;
  bool visible = true;
};

// The window's members are split by concept: events and the loop in
// desktop_window.cpp, the scene in desktop_window_scene.cpp, files in
// desktop_window_outputs.cpp.
class DesktopWindow {
 public:
  DesktopWindow(ViewerModel& model, std::shared_ptr<PointerInput> input,
                const WindowOptions& options);
  ~DesktopWindow();
  int run();

 private:
  // Layout and camera.
  int viewport_at(double gl_x) const;  // stack index under a pixel column
  std::array<int, 4> viewport_pixels(int stack) const;  // x0, y0, w, h
  View view_of(int stack) const;
  void fit_camera_to_scene();
  Box3 bounds() const;
  std::vector<const Sketch*> framed_sketches() const;

  // Input.
  void on_pointer(const XPointerEvent& e);
  void on_key(unsigned long keysym, unsigned modifiers);
  void on_resize(int width, int height);
  void command(EventPayload payload);
  void pump_input();
  double now() const;
  std::optional<Vec3> cursor_on_plane() const;
  std::optional<Vec3> nearest_curve_point(double& radius) const;
  void seek_timeline(double gl_x);

  // Actions.
  void save_recording();
  void export_json();
  void export_meshes();
  void screenshot();
  void notify(const std::string& message);

  // Drawing.
  void rebuild_scene();
  void update_overlay();
  void update_live_stroke();
  void render();

  ViewerModel& model_;
  std::shared_ptr<PointerInput> input_;
  ViewOptions options_;
  viewer::SceneStyle style_;

  vtkSmartPointer<vtkRenderWindow> window_;
  vtkSmartPointer<vtkCamera> camera_;
  std::vector<vtkSmartPointer<vtkRenderer>> renderers_;
  vtkSmartPointer<vtkRenderer> overlay_;
  std::vector<std::vector<vtkSmartPointer<vtkProp>>> scene_props_;  // per stack
  vtkSmartPointer<vtkTextActor> status_, help_, message_;
  vtkSmartPointer<vtkActor2D> timeline_, live_stroke_;
  std::unique_ptr<XPointer> pointer_;

  int width_ = 0, height_ = 0;
  DrawPlane plane_;
  Sketch recording_strokes_;  // the opened recording's 3D strokes, for framing
  double scene_size_ = 1.0;
  bool help_visible_ = false, markers_visible_ = false;
  bool playing_ = false, running_ = true, dirty_ = true, overlay_dirty_ = true;
  Layer mode_ = Layer::automatic;
  enum class Drag { none, draw, orbit, pan, scrub } drag_ = Drag::none;
  int draw_stack_ = 0;
  double last_x_ = 0, last_y_ = 0;  // X coordinates of the last pointer event
  double time_base_ = 0;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_play_step_;
  int screenshots_ = 0;
  std::string message_text_;
  std::vector<Vec2> live_trace_;  // pen trace in window pixels (GL origin)
};

}  // namespace sketchlab::desktop
