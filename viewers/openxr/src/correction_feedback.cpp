#include "correction_feedback.hpp"

#include <algorithm>

#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>

#include "constraint_markers.hpp"
#include "sketchlab/geometry/arclength.hpp"
#include "sketchlab/geometry/bezier.hpp"
#include "vr_actor_utils.hpp"

namespace sketchlab::vr {
namespace {

std::vector<Vec3> positions(const std::vector<Sample>& samples) {
  std::vector<Vec3> out;
  out.reserve(samples.size());
  for (const Sample& s : samples) out.push_back(s.position);
  return out;
}

vtkSmartPointer<vtkPolyData> polylines(const std::deque<std::vector<Vec3>>& lines) {
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> cells;
  for (const auto& line : lines) {
    if (line.size() < 2) continue;
    cells->InsertNextCell(static_cast<vtkIdType>(line.size()));
    for (const Vec3& p : line) cells->InsertCellPoint(points->InsertNextPoint(p.data()));
  }
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  data->SetLines(cells);
  return data;
}

// The curves made from `stroke`, sampled every `spacing` metres.
std::deque<std::vector<Vec3>> curves_of(const Sketch& sketch, StrokeId stroke, double spacing) {
  std::deque<std::vector<Vec3>> out;
  for (const auto& [id, c] : sketch.network.curves()) {
    if (c.source_stroke != stroke) continue;
    const int n = std::clamp(static_cast<int>(arclength(c.curve) / spacing), 8, 2000);
    out.emplace_back();
    for (int i = 0; i <= n; ++i) out.back().push_back(evaluate(c.curve, c.curve.t_max() * i / n));
  }
  return out;
}

vtkSmartPointer<vtkActor> line_actor(const viewer::Rgb& colour, double width) {
  auto a = actor_for(vtkNew<vtkPolyData>().GetPointer());
  set_colour(a, colour);
  a->GetProperty()->SetLineWidth(static_cast<float>(width));
  a->GetProperty()->LightingOff();
  return a;
}

}  // namespace

double flash_opacity(double age) {
  if (age < 0.0) return 1.0;
  const double hold = flash_s * 2.0 / 3.0;
  return age <= hold ? 1.0 : std::max(0.0, 1.0 - (age - hold) / (flash_s - hold));
}

CorrectionFeedback::CorrectionFeedback(vtkRenderer* renderer, const viewer::SceneStyle& style)
    : renderer_(renderer), style_(style) {
  live_ = line_actor(style.curve_colour, style.curve_width);
  pending_actor_ = line_actor(style.curve_colour, style.curve_width);
  fading_ = line_actor(style.curve_colour, style.curve_width);
  glow_ = line_actor(glow_colour, style.curve_width + 2.0);
  for (vtkActor* a : {live_.Get(), pending_actor_.Get(), fading_.Get(), glow_.Get()}) renderer_->AddActor(a);
  fading_->VisibilityOff();
  glow_->VisibilityOff();
}

void CorrectionFeedback::set_live_stroke(const std::vector<Sample>& samples) {
  set_data(live_, polyline_data(positions(samples)));
}

void CorrectionFeedback::stroke_submitted(const Stroke& stroke) {
  ++submitted_;
  pending_.push_back(positions(stroke.samples));
  set_data(pending_actor_, polylines(pending_));
}

void CorrectionFeedback::clear_flash() {
  for (const Flash& f : flash_) renderer_->RemoveActor(f.actor);
  flash_.clear();
}

void CorrectionFeedback::corrected(std::size_t strokes_handled, StrokeId stroke, const Sketch& sketch,
                                   const std::vector<Constraint>& constraints, bool show_rejected, double now) {
  // Strokes still queued behind this snapshot stay pending.
  const std::size_t still_queued = submitted_ > strokes_handled ? submitted_ - strokes_handled : 0;
  std::deque<std::vector<Vec3>> done;
  while (pending_.size() > still_queued) {
    done.push_back(std::move(pending_.front()));
    pending_.pop_front();
  }
  set_data(pending_actor_, polylines(pending_));
  set_data(fading_, polylines(done));
  set_data(glow_, polylines(curves_of(sketch, stroke, 0.002)));
  fade_start_ = now;
  fading_->VisibilityOn();
  glow_->VisibilityOn();

  clear_flash();
  flash_start_ = now;
  for (bool rejected : {false, true}) {
    if (rejected && !show_rejected) continue;
    const viewer::ConstraintMarkers m = viewer::make_constraint_markers(constraints, sketch, marker_size, rejected);
    for (const auto& a : {m.coincidence, m.right_angles, m.tangents, m.planes}) {
      if (!a) continue;
      renderer_->AddActor(a);
      flash_.push_back({a, a->GetProperty()->GetOpacity()});
    }
  }
}

void CorrectionFeedback::update(vtkMatrix4x4* placement, double now) {
  for (vtkActor* a : {live_.Get(), pending_actor_.Get(), fading_.Get(), glow_.Get()}) a->SetUserMatrix(placement);
  if (fade_start_ >= 0.0) {
    const double t = (now - fade_start_) / transition_s;
    if (t >= 2.0) {
      fading_->VisibilityOff();
      glow_->VisibilityOff();
      fade_start_ = -1.0;
    } else {
      // The raw stroke fades over transition_s; the glow over twice that.
      fading_->GetProperty()->SetOpacity(std::clamp(1.0 - t, 0.0, 1.0));
      fading_->SetVisibility(t < 1.0);
      glow_->GetProperty()->SetOpacity(std::clamp(1.0 - 0.5 * t, 0.0, 1.0));
    }
  }
  if (!flash_.empty()) {
    const double k = flash_opacity(now - flash_start_);
    if (k <= 0.0) {
      clear_flash();
    } else {
      for (const Flash& f : flash_) {
        f.actor->SetUserMatrix(placement);
        f.actor->GetProperty()->SetOpacity(k * f.opacity);
      }
    }
  }
}

}  // namespace sketchlab::vr
