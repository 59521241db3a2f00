// DesktopWindow's scene: the viewports' actors rebuilt from the stacks'
// sketches, the 2D overlay (titles, figures, timeline, help) and the stroke
// being drawn.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCoordinate.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataMapper2D.h>
#include <vtkProperty.h>
#include <vtkProperty2D.h>
#include <vtkTextProperty.h>
#include <vtkUnsignedCharArray.h>

#include "desktop_window.hpp"
#include "sketchlab/draw_plane.hpp"

namespace sketchlab::desktop {
namespace {

vtkSmartPointer<vtkActor2D> polyline_2d(const std::vector<Vec2>& points, const viewer::Rgb& colour,
                                        double width) {
  vtkNew<vtkPoints> pts;
  vtkNew<vtkCellArray> lines;
  if (points.size() >= 2) {
    lines->InsertNextCell(static_cast<vtkIdType>(points.size()));
    for (const Vec2& p : points) lines->InsertCellPoint(pts->InsertNextPoint(p.x(), p.y(), 0.0));
  }
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(pts);
  poly->SetLines(lines);
  vtkNew<vtkPolyDataMapper2D> mapper;
  mapper->SetInputData(poly);
  auto actor = vtkSmartPointer<vtkActor2D>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(colour[0], colour[1], colour[2]);
  actor->GetProperty()->SetLineWidth(static_cast<float>(width));
  return actor;
}

// The draw plane as a light square outline with a faint fill, `size` wide.
std::vector<vtkSmartPointer<vtkProp>> plane_props(const DrawPlane& plane, double size) {
  const Vec3 n = plane.plane.normal.normalized();
  const Vec3 u = n.unitOrthogonal(), v = n.cross(u).normalized();
  const double h = 0.5 * size;
  const Vec3& o = plane.plane.point;
  const Vec3 c[4] = {o - h * u - h * v, o + h * u - h * v, o + h * u + h * v, o - h * u + h * v};
  std::vector<vtkSmartPointer<vtkProp>> out;
  for (int fill = 0; fill < 2; ++fill) {
    vtkNew<vtkPoints> pts;
    for (const Vec3& p : c) pts->InsertNextPoint(p.x(), p.y(), p.z());
    vtkNew<vtkCellArray> cells;
    const vtkIdType loop[5] = {0, 1, 2, 3, 0};
    cells->InsertNextCell(fill ? 4 : 5, loop);
    vtkNew<vtkPolyData> poly;
    poly->SetPoints(pts);
    if (fill) poly->SetPolys(cells);
    else poly->SetLines(cells);
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(poly);
    // Curves drawn on the plane lie exactly in it: push the fill back so it
    // never covers them.
    mapper->SetRelativeCoincidentTopologyPolygonOffsetParameters(2.0, 2.0);
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    actor->GetProperty()->LightingOff();
    actor->GetProperty()->SetColor(0.62, 0.75, 0.92);
    actor->GetProperty()->SetOpacity(fill ? 0.07 : 0.9);
    actor->GetProperty()->SetLineWidth(1.0f);
    actor->PickableOff();
    out.push_back(actor);
  }
  return out;
}

}  // namespace

void DesktopWindow::rebuild_scene() {
  // Chords of curve_spacing_pixels at the focal distance, as the offscreen
  // renderer: much finer chords make VTK's wide lines break up.
  const double distance = camera_->GetDistance();
  const double metres_per_pixel =
      2.0 * distance * std::tan(0.5 * camera_->GetViewAngle() * std::numbers::pi / 180.0) / height_;
  const double spacing = std::max(style_.curve_spacing_pixels * metres_per_pixel, 1e-6);
  for (std::size_t i = 0; i < renderers_.size(); ++i) {
    vtkRenderer* r = renderers_[i];
    for (auto& p : scene_props_[i]) r->RemoveViewProp(p);
    scene_props_[i].clear();
    const Sketch& sketch = model_.sketch(i);
    // Raw strokes: 2D ones drawn on a plane are shown lifted onto it.
    std::vector<Stroke> raw;
    for (const auto& [id, s] : sketch.strokes) {
      std::string error;
      Stroke lifted = lift_to_draw_plane(s, error);
      if (!lifted.samples_are_pixels) raw.push_back(std::move(lifted));
    }
    const viewer::SceneActors a = viewer::add_sketch_actors(r, sketch, &raw, style_, spacing);
    // Raw strokes drawn on the plane coincide with their curves: keep them
    // behind, so they never streak the dark curve.
    if (a.raw_strokes)
      if (auto* m = a.raw_strokes->GetMapper())
        m->SetRelativeCoincidentTopologyLineOffsetParameters(0.0, 6.0);
    for (auto* p : {a.raw_strokes.Get(), a.scaffold_curves.Get(), a.shape_curves.Get(),
                    a.other_curves.Get(), a.nodes.Get(), a.patches.Get()})
      if (p) scene_props_[i].push_back(p);
    if (markers_visible_) {
      if (const StepReport* rep = model_.last_stroke_report(i)) {
        const auto m = viewer::make_constraint_markers(rep->constraints, sketch, 0.01 * scene_size_);
        for (auto* p : {m.coincidence.Get(), m.right_angles.Get(), m.tangents.Get(), m.planes.Get()})
          if (p) {
            r->AddActor(p);
            scene_props_[i].push_back(p);
          }
      }
    }
    if (plane_.visible)
      for (auto& p : plane_props(plane_, 0.6 * std::max(scene_size_, 0.5))) {
        r->AddViewProp(p);
        scene_props_[i].push_back(p);
      }
    // Title and figures.
    std::ostringstream fig;
    fig << sketch.network.curves().size() << " curves, " << sketch.network.nodes().size()
        << " nodes, " << sketch.network.patches().size() << " patches";
    if (const StepReport* rep = model_.last_stroke_report(i)) {
      fig.precision(1);
      fig << std::fixed << "\nlast stroke " << rep->latency_ms << " ms";
      if (markers_visible_) {
        int enforced = 0;
        for (const auto& c : rep->constraints) enforced += c.enforced ? 1 : 0;
        fig << ", " << enforced << " constraints";
      }
    }
    auto title = viewer::make_text(model_.stack_name(i), 0.025, 0.975, true, 20,
                                   style_.text_colour, false);
    auto figures = viewer::make_text(fig.str(), 0.025, 0.035, false, 14, style_.text_colour, true);
    for (vtkProp* p : {static_cast<vtkProp*>(title.Get()), static_cast<vtkProp*>(figures.Get())}) {
      r->AddViewProp(p);
      scene_props_[i].push_back(p);
    }
    if (i > 0) {
      auto sep = viewer::make_left_separator(style_.separator_colour);
      r->AddViewProp(sep);
      scene_props_[i].push_back(sep);
    }
  }
  overlay_dirty_ = true;
}

void DesktopWindow::update_overlay() {
  std::ostringstream s;
  s << to_string(model_.sketch(0).mode) << " | correction "
    << (model_.sketch(0).correction_enabled ? "on" : "off") << " | ";
  if (const ReplayController* r = model_.replay(); r && r->event_count() > 0)
    s << "stroke " << r->stop_index() << "/" << r->stroke_count() << (playing_ ? " >" : "");
  else
    s << "live";
  s << " | h: help";
  status_->SetInput(s.str().c_str());
  help_->SetVisibility(help_visible_);
  message_->SetInput(message_text_.c_str());

  if (timeline_) overlay_->RemoveViewProp(timeline_);
  timeline_ = nullptr;
  if (const ReplayController* r = model_.replay(); r && r->stroke_count() > 0) {
    const double f = static_cast<double>(r->stop_index()) / r->stroke_count();
    const double y = 0.5 * timeline_height;
    vtkNew<vtkPoints> pts;
    vtkNew<vtkCellArray> lines;
    const vtkIdType a = pts->InsertNextPoint(0, y, 0), b = pts->InsertNextPoint(f * width_, y, 0);
    const vtkIdType c = pts->InsertNextPoint(f * width_, y, 0), d = pts->InsertNextPoint(width_, y, 0);
    lines->InsertNextCell(2, std::array<vtkIdType, 2>{a, b}.data());
    lines->InsertNextCell(2, std::array<vtkIdType, 2>{c, d}.data());
    vtkNew<vtkPolyData> poly;
    poly->SetPoints(pts);
    poly->SetLines(lines);
    vtkNew<vtkUnsignedCharArray> colours;
    colours->SetNumberOfComponents(3);
    colours->InsertNextTypedTuple(std::array<unsigned char, 3>{70, 120, 200}.data());
    colours->InsertNextTypedTuple(std::array<unsigned char, 3>{215, 222, 232}.data());
    poly->GetCellData()->SetScalars(colours);
    vtkNew<vtkPolyDataMapper2D> mapper;
    mapper->SetInputData(poly);
    timeline_ = vtkSmartPointer<vtkActor2D>::New();
    timeline_->SetMapper(mapper);
    timeline_->GetProperty()->SetLineWidth(6.0f);
    overlay_->AddViewProp(timeline_);
  }
  update_live_stroke();
}

void DesktopWindow::update_live_stroke() {
  if (live_stroke_) overlay_->RemoveViewProp(live_stroke_);
  live_stroke_ = nullptr;
  if (drag_ != Drag::draw || live_trace_.size() < 2) return;
  live_stroke_ = polyline_2d(live_trace_, style_.curve_colour, 2.0);
  overlay_->AddViewProp(live_stroke_);
}


}  // namespace sketchlab::desktop
