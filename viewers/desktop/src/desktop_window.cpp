#include "desktop_window.hpp"

#include <poll.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <numbers>

#include <vtkCoordinate.h>
#include <vtkNew.h>
#include <vtkTextProperty.h>

#include "sketchlab/draw_plane.hpp"
#include "sketchlab/geometry/arclength.hpp"
#include "sketchlab/viewer/camera.hpp"

// Xlib last: its macros (None, Success, Status...) break VTK's headers.
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <X11/keysym.h>

namespace sketchlab::desktop {

DesktopWindow::DesktopWindow(ViewerModel& model, std::shared_ptr<PointerInput> input,
                             const WindowOptions& options)
    : model_(model), input_(std::move(input)), options_(options.options) {
  width_ = std::clamp(options_.width, 200, 8192);
  height_ = std::clamp(options_.height, 150, 8192);
  start_ = last_play_step_ = std::chrono::steady_clock::now();
  playing_ = options_.play;
  style_.multisamples = std::max(0, options_.multisamples);
  // Live times continue after everything the opened recording holds.
  if (ReplayController* r = model_.replay(); r && r->event_count() > 0)
    time_base_ = r->recording().events.back().time + 1.0;
  if (ReplayController* r = model_.replay(); r && options_.at_stroke) r->seek_stop(*options_.at_stroke);
  if (ReplayController* r = model_.replay()) {
    recording_strokes_.workspace = r->recording().header.workspace;
    for (const Event& e : r->recording().events)
      if (const auto* st = std::get_if<StrokeEvent>(&e.payload); st && !st->stroke.samples_are_pixels)
        recording_strokes_.strokes.emplace(st->stroke.id, st->stroke);
  }

  window_ = vtkSmartPointer<vtkRenderWindow>::New();
  window_->SetSize(width_, height_);
  window_->SetMultiSamples(style_.multisamples);
  window_->SetNumberOfLayers(2);
  // Renamed "sketchlab view" once input is selected: whoever waits for the
  // window by name (scripts, tests) then loses no event.
  window_->SetWindowName("sketchlab view (starting)");
  camera_ = vtkSmartPointer<vtkCamera>::New();
  const int n = static_cast<int>(model_.stack_count());
  for (int i = 0; i < n; ++i) {
    auto r = vtkSmartPointer<vtkRenderer>::New();
    r->SetViewport(static_cast<double>(i) / n, 0.0, static_cast<double>(i + 1) / n, 1.0);
    r->SetBackground(style_.background[0], style_.background[1], style_.background[2]);
    r->SetActiveCamera(camera_);  // linked: every viewport shares the camera
    r->SetLayer(0);
    window_->AddRenderer(r);
    renderers_.push_back(r);
  }
  scene_props_.resize(renderers_.size());
  overlay_ = vtkSmartPointer<vtkRenderer>::New();
  overlay_->SetLayer(1);
  overlay_->InteractiveOff();
  window_->AddRenderer(overlay_);
  const auto& tc = style_.text_colour;
  status_ = viewer::make_text("", 0.995, 0.985, true, 14, tc, true);
  status_->GetTextProperty()->SetJustificationToRight();
  help_ = viewer::make_text(help_text(), 0.22, 0.93, true, 15, tc, true);
  help_->GetTextProperty()->SetBackgroundColor(1.0, 1.0, 0.94);
  help_->GetTextProperty()->SetBackgroundOpacity(0.93);
  help_->SetVisibility(false);
  message_ = viewer::make_text("", 0.995, 0.035, false, 14, {0.1, 0.3, 0.6}, true);
  message_->GetTextProperty()->SetJustificationToRight();
  overlay_->AddActor2D(status_);
  overlay_->AddActor2D(help_);
  overlay_->AddActor2D(message_);

  window_->Render();  // creates the X window
  auto* display = static_cast<Display*>(window_->GetGenericDisplayId());
  const auto xwindow = reinterpret_cast<Window>(window_->GetGenericWindowId());
  XSelectInput(display, xwindow, KeyPressMask | ExposureMask | StructureNotifyMask);
  pointer_ = std::make_unique<XPointer>(display, xwindow);
  XSetInputFocus(display, xwindow, RevertToParent, CurrentTime);
  XStoreName(display, xwindow, "sketchlab view");
  XSync(display, False);
  fit_camera_to_scene();
  // Default draw plane: through the scene centre, facing the camera.
  plane_.plane.point = Vec3(camera_->GetFocalPoint());
  plane_.plane.normal = (Vec3(camera_->GetPosition()) - plane_.plane.point).normalized();
}

DesktopWindow::~DesktopWindow() = default;

std::array<int, 4> DesktopWindow::viewport_pixels(int stack) const {
  const int n = static_cast<int>(renderers_.size());
  const int x0 = stack * width_ / n, x1 = (stack + 1) * width_ / n;
  return {x0, 0, x1 - x0, height_};
}

int DesktopWindow::viewport_at(double gl_x) const {
  const int n = static_cast<int>(renderers_.size());
  for (int i = 0; i < n; ++i) {
    const auto vp = viewport_pixels(i);
    if (gl_x < vp[0] + vp[2]) return i;
  }
  return n - 1;
}

View DesktopWindow::view_of(int stack) const {
  // The same frustum VTK renders with (vertical view angle, symmetric).
  const auto vp = viewport_pixels(stack);
  View v;
  v.view = look_at(Vec3(camera_->GetPosition()), Vec3(camera_->GetFocalPoint()),
                   Vec3(camera_->GetViewUp()));
  double range[2];
  camera_->GetClippingRange(range);
  v.projection = perspective(camera_->GetViewAngle() * std::numbers::pi / 180.0,
                             static_cast<double>(vp[2]) / vp[3], range[0], range[1]);
  v.viewport = Vec4(vp[0], vp[1], vp[2], vp[3]);
  return v;
}

std::vector<const Sketch*> DesktopWindow::framed_sketches() const {
  std::vector<const Sketch*> sketches;
  for (std::size_t i = 0; i < model_.stack_count(); ++i) sketches.push_back(&model_.sketch(i));
  sketches.push_back(&recording_strokes_);
  return sketches;
}

Box3 DesktopWindow::bounds() const { return viewer::scene_bounds(framed_sketches()); }

void DesktopWindow::fit_camera_to_scene() {
  // Frames the sketches and every 3D stroke of the opened recording, so the
  // camera fits the whole session and does not jump while scrubbing.
  const std::vector<const Sketch*> sketches = framed_sketches();
  const auto vp = viewport_pixels(0);
  viewer::Camera c = viewer::fit_camera(sketches, viewer::ViewDirection::iso,
                                        static_cast<double>(vp[2]) / vp[3]);
  const Box3 b = bounds();
  scene_size_ = b.isEmpty() ? 1.0 : std::max(b.diagonal().norm(), 1e-3);
  if (b.isEmpty()) {
    // Nothing yet: look at the unit-sized workspace from the front.
    c.focal_point = Vec3::Zero();
    const Vec3 up = model_.sketch(0).workspace.up;
    const Vec3 front = std::abs(up.z()) > 0.9 ? Vec3(0, -1, 0) : Vec3(0, 0, 1);
    c.position = front * 2.0;
    c.view_up = up;
    scene_size_ = 1.0;
  }
  camera_->SetPosition(c.position.data());
  camera_->SetFocalPoint(c.focal_point.data());
  camera_->SetViewUp(c.view_up.data());
  camera_->SetViewAngle(c.view_angle_deg);
  plane_.plane.point = c.focal_point;  // the draw plane follows the framed scene
  dirty_ = true;
}

double DesktopWindow::now() const {
  return time_base_ +
         std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void DesktopWindow::notify(const std::string& message) {
  std::cout << message << std::endl;
  message_text_ = message;
  overlay_dirty_ = true;
}

void DesktopWindow::command(EventPayload payload) {
  // Strokes drawn after this continue the replayed prefix's ids.
  if (!model_.live()) input_->set_next_stroke_id(model_.next_stroke_id());
  input_->command(Event{now(), std::move(payload)});
  pump_input();
}

void DesktopWindow::pump_input() {
  while (auto e = input_->next()) {
    try {
      const auto reports = model_.handle_live(*e);
      for (std::size_t i = 0; i < reports.size(); ++i)
        if (!reports[i].error.empty())
          notify(model_.stack_name(i) + ": " + reports[i].error);
    } catch (const std::exception& ex) {
      notify(std::string("not recorded: ") + ex.what());
    }
    playing_ = false;
    dirty_ = true;
  }
}

std::optional<Vec3> DesktopWindow::cursor_on_plane() const {
  const double gx = last_x_ + 0.5, gy = height_ - last_y_ - 0.5;
  Vec3 p;
  const Vec4 plane = plane_through(plane_.plane.point, plane_.plane.normal);
  if (pixel_on_plane(view_of(viewport_at(gx)), plane, {gx, gy}, p)) return p;
  return std::nullopt;
}

std::optional<Vec3> DesktopWindow::nearest_curve_point(double& radius) const {
  const double gx = last_x_ + 0.5, gy = height_ - last_y_ - 0.5;
  const int stack = viewport_at(gx);
  const View v = view_of(stack);
  const Sketch& sketch = model_.sketch(static_cast<std::size_t>(stack));
  double best = 25.0;  // pixels
  std::optional<Vec3> hit;
  const double spacing = std::max(scene_size_ * 0.002, 1e-5);
  for (const auto& [id, curve] : sketch.network.curves()) {
    for (const Vec3& p : sample_with_spacing(curve.curve, spacing)) {
      const Vec3 px = world_to_pixel(v, p);
      if (px.z() < 0) continue;
      const double d = (px.head<2>() - Vec2(gx, gy)).norm();
      if (d < best) best = d, hit = p;
    }
  }
  if (hit) {
    // 10 pixels at the point's distance from the eye.
    const double dist = (*hit - eye_position(v)).norm();
    radius = 10.0 * 2.0 * dist * std::tan(0.5 * camera_->GetViewAngle() * std::numbers::pi / 180.0) /
             height_;
  }
  return hit;
}

void DesktopWindow::seek_timeline(double gl_x) {
  ReplayController* r = model_.replay();
  if (!r || r->stroke_count() == 0) return;
  const double f = std::clamp(gl_x / width_, 0.0, 1.0);
  r->seek_stop(static_cast<std::size_t>(std::lround(f * r->stroke_count())));
  playing_ = false;
  dirty_ = true;
}

void DesktopWindow::on_pointer(const XPointerEvent& e) {
  const double dx = e.x - last_x_, dy = e.y - last_y_;
  last_x_ = e.x;
  last_y_ = e.y;
  const double gx = e.x + 0.5, gy = height_ - e.y - 0.5;
  const PointerSample sample{{gx, gy}, now(), e.pressure};
  using T = XPointerEvent::Type;
  if (e.type == T::press) {
    if (e.button == 4 || e.button == 5) {
      camera_->Dolly(e.button == 4 ? 1.1 : 1.0 / 1.1);
      dirty_ = true;
      return;
    }
    if (drag_ != Drag::none) return;
    if (e.button == 1 && gy < timeline_height && model_.replay()) {
      drag_ = Drag::scrub;
      seek_timeline(gx);
    } else if (e.button == 1) {
      drag_ = Drag::draw;
      draw_stack_ = viewport_at(gx);
      playing_ = false;
      if (!model_.live()) input_->set_next_stroke_id(model_.next_stroke_id());
      PointerContext ctx;
      ctx.view = view_of(draw_stack_);
      ctx.draw_plane = plane_through(plane_.plane.point, plane_.plane.normal);
      ctx.layer = Layer::automatic;  // the recorded mode event decides
      ctx.workspace_scale = model_.sketch(0).workspace.scale;
      input_->pen_down(sample, ctx);
      live_trace_.assign(1, Vec2(gx, gy));
    } else if (e.button == 3 && e.shift) {
      drag_ = Drag::pan;
    } else if (e.button == 3) {
      drag_ = Drag::orbit;
    } else if (e.button == 2) {
      drag_ = Drag::pan;
    }
    return;
  }
  if (e.type == T::motion) {
    switch (drag_) {
      case Drag::draw:
        input_->pen_move(sample);
        live_trace_.push_back({gx, gy});
        overlay_dirty_ = true;
        break;
      case Drag::orbit:
        camera_->Azimuth(-0.4 * dx);
        camera_->Elevation(0.4 * dy);
        camera_->OrthogonalizeViewUp();
        dirty_ = true;
        break;
      case Drag::pan: {
        const Vec3 pos(camera_->GetPosition()), focal(camera_->GetFocalPoint());
        const Vec3 up = Vec3(camera_->GetViewUp()).normalized();
        const Vec3 right = (focal - pos).cross(up).normalized();
        const double mpp = 2.0 * (focal - pos).norm() *
                           std::tan(0.5 * camera_->GetViewAngle() * std::numbers::pi / 180.0) / height_;
        const Vec3 shift = (-dx * right + dy * up) * mpp;
        const Vec3 new_pos = pos + shift, new_focal = focal + shift;
        camera_->SetPosition(new_pos.data());
        camera_->SetFocalPoint(new_focal.data());
        dirty_ = true;
        break;
      }
      case Drag::scrub: seek_timeline(gx); break;
      case Drag::none: break;
    }
    return;
  }
  // release
  if (drag_ == Drag::draw && e.button == 1) {
    input_->pen_up(sample);
    drag_ = Drag::none;
    live_trace_.clear();
    overlay_dirty_ = true;
    pump_input();
  } else if ((drag_ == Drag::scrub && e.button == 1) ||
             ((drag_ == Drag::orbit || drag_ == Drag::pan) && (e.button == 2 || e.button == 3))) {
    drag_ = Drag::none;
  }
}

void DesktopWindow::on_key(unsigned long key, unsigned modifiers) {
  const bool ctrl = modifiers & ControlMask;
  ReplayController* r = model_.replay();
  auto mode = [&](Layer l) {
    mode_ = l;
    command(ModeEvent{l});
    overlay_dirty_ = true;
  };
  auto move_plane = [&](double sign) {
    plane_.plane.point += sign * 0.05 * scene_size_ * plane_.plane.normal;
    dirty_ = true;
  };
  auto axis_plane = [&](const Vec3& n) {
    plane_.plane.normal = n;
    plane_.visible = true;
    dirty_ = true;
  };
  switch (key) {
    case XK_q: case XK_Escape: running_ = false; break;
    case XK_h: case XK_F1: help_visible_ = !help_visible_; overlay_dirty_ = true; break;
    case XK_1: mode(Layer::scaffold); break;
    case XK_2: mode(Layer::shape); break;
    case XK_3: mode(Layer::free); break;
    case XK_4: mode(Layer::automatic); break;
    case XK_u: command(UndoEvent{}); break;
    case XK_r: command(RedoEvent{}); break;
    case XK_z: if (ctrl) command(UndoEvent{}); else axis_plane(Vec3::UnitZ()); break;
    case XK_y: if (ctrl) command(RedoEvent{}); else axis_plane(Vec3::UnitY()); break;
    case XK_x: axis_plane(Vec3::UnitX()); break;
    case XK_v:
      plane_.plane.normal = (Vec3(camera_->GetPosition()) - Vec3(camera_->GetFocalPoint())).normalized();
      plane_.visible = true;
      dirty_ = true;
      break;
    case XK_bracketleft: move_plane(-1); break;
    case XK_bracketright: move_plane(1); break;
    case XK_g: plane_.visible = !plane_.visible; dirty_ = true; break;
    case XK_d: {
      double radius = 0;
      if (auto p = nearest_curve_point(radius)) command(DeleteNearEvent{*p, radius});
      else notify("delete: no curve near the cursor");
      break;
    }
    case XK_a: {
      double radius = 0;
      auto p = cursor_on_plane();
      if (!p) p = nearest_curve_point(radius);
      if (p) command(AddPatchEvent{*p});
      else notify("add patch: the cursor is not over the draw plane");
      break;
    }
    case XK_c: command(CorrectionEvent{!model_.sketch(0).correction_enabled}); break;
    case XK_k: markers_visible_ = !markers_visible_; dirty_ = true; break;
    case XK_f: fit_camera_to_scene(); break;
    case XK_s: save_recording(); break;
    case XK_j: export_json(); break;
    case XK_e: export_meshes(); break;
    case XK_p: screenshot(); break;
    case XK_space:
      if (r) playing_ = !playing_, last_play_step_ = std::chrono::steady_clock::now();
      overlay_dirty_ = true;
      break;
    case XK_Right: case XK_period: if (r) r->step_forward(), playing_ = false, dirty_ = true; break;
    case XK_Left: case XK_comma: if (r) r->step_back(), playing_ = false, dirty_ = true; break;
    case XK_Next: if (r) r->seek_stop(r->stop_index() + 10), dirty_ = true; break;
    case XK_Prior:
      if (r) r->seek_stop(r->stop_index() >= 10 ? r->stop_index() - 10 : 0), dirty_ = true;
      break;
    case XK_Home: if (r) r->seek(0), dirty_ = true; break;
    case XK_End: if (r) r->seek(r->event_count()), dirty_ = true; break;
    default: break;
  }
}

void DesktopWindow::render() {
  if (dirty_) {
    rebuild_scene();
    dirty_ = false;
  }
  if (overlay_dirty_) {
    update_overlay();
    overlay_dirty_ = false;
  }
  // One clipping range for the shared camera, from every viewport's props.
  double all[6] = {1, -1, 1, -1, 1, -1};
  for (auto& r : renderers_) {
    double b[6];
    r->ComputeVisiblePropBounds(b);
    if (b[0] > b[1]) continue;
    for (int k = 0; k < 3; ++k) {
      if (all[2 * k] > all[2 * k + 1]) all[2 * k] = b[2 * k], all[2 * k + 1] = b[2 * k + 1];
      all[2 * k] = std::min(all[2 * k], b[2 * k]);
      all[2 * k + 1] = std::max(all[2 * k + 1], b[2 * k + 1]);
    }
  }
  if (all[0] <= all[1]) renderers_.front()->ResetCameraClippingRange(all);
  window_->Render();
}

void DesktopWindow::on_resize(int width, int height) {
  if (width == width_ && height == height_) return;
  width_ = width;
  height_ = height;
  window_->SetSize(width, height);
  dirty_ = true;
}

int DesktopWindow::run() {
  auto* display = static_cast<Display*>(window_->GetGenericDisplayId());
  const Atom wm_delete = XInternAtom(display, "WM_DELETE_WINDOW", False);
  const auto xwindow = reinterpret_cast<Window>(window_->GetGenericWindowId());
  Atom protocols[1] = {wm_delete};
  XSetWMProtocols(display, xwindow, protocols, 1);
  render();
  std::cout << "sketchlab view: window 0x" << std::hex << xwindow << std::dec << " ready"
            << std::endl;
  while (running_) {
    while (XPending(display) > 0) {
      XEvent ev;
      XNextEvent(display, &ev);
      if (auto p = pointer_->decode(&ev)) {
        if (std::getenv("SKETCHLAB_VIEW_DEBUG"))
          std::cerr << "pointer " << static_cast<int>(p->type) << " b" << p->button << " " << p->x
                    << "," << p->y << "\n";
        on_pointer(*p);
        continue;
      }
      switch (ev.type) {
        case KeyPress: {
          const KeySym sym = XLookupKeysym(&ev.xkey, 0);
          if (std::getenv("SKETCHLAB_VIEW_DEBUG")) std::cerr << "key " << sym << "\n";
          on_key(sym, ev.xkey.state);
          break;
        }
        case Expose: overlay_dirty_ = true; break;
        case ConfigureNotify: on_resize(ev.xconfigure.width, ev.xconfigure.height); break;
        case ClientMessage:
          if (static_cast<Atom>(ev.xclient.data.l[0]) == wm_delete) running_ = false;
          break;
        default: break;
      }
    }
    if (!running_) break;
    if (playing_) {
      ReplayController* r = model_.replay();
      const auto t = std::chrono::steady_clock::now();
      if (!r || r->at_end()) {
        playing_ = false;
        overlay_dirty_ = true;
      } else if (std::chrono::duration<double>(t - last_play_step_).count() >= options_.play_interval) {
        r->step_forward();
        last_play_step_ = t;
        dirty_ = true;
      }
    }
    if (dirty_ || overlay_dirty_) render();
    pollfd fd{ConnectionNumber(display), POLLIN, 0};
    poll(&fd, 1, 15);
  }
  input_->close();
  pump_input();
  return 0;
}

}  // namespace sketchlab::desktop
