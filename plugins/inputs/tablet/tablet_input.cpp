#include "tablet_input.hpp"

#include <algorithm>
#include <cmath>

#include "sketchlab/geometry/polyline.hpp"

namespace sketchlab::tablet {

bool keep_sample(const std::vector<Sample>& kept, const Vec2& pixel, double min_spacing) {
  if (!pixel.allFinite()) return false;
  if (kept.empty()) return true;
  return (pixel - kept.back().position.head<2>()).norm() >= std::max(min_spacing, 1e-12);
}

TabletInput::TabletInput(const TabletParams& params) : params_(params) {}

RecordingHeader TabletInput::header() const {
  RecordingHeader h;
  h.units = "px";
  h.workspace.up = params_.up;
  h.source = {{"input", "tablet"}, {"device", "pointer (XInput2 pen or mouse)"}};
  return h;
}

NextEvent TabletInput::next() {
  if (queue_.empty()) return closed_ ? NextEvent::ended() : NextEvent::not_ready();
  Event e = std::move(queue_.front());
  queue_.pop_front();
  return e;
}

void TabletInput::push(Event event) {
  // Recordings need non-decreasing times; pointer and clock times may differ
  // by a little, so clamp.
  if (!std::isfinite(event.time)) event.time = last_time_;
  event.time = std::max(event.time, last_time_);
  last_time_ = event.time;
  queue_.push_back(std::move(event));
}

static Sample to_sample(const PointerSample& p) {
  Sample s;
  s.position = Vec3(p.pixel.x(), p.pixel.y(), 0.0);
  s.time = p.time;
  s.pressure = std::isfinite(p.pressure) ? std::clamp(p.pressure, 0.0, 1.0) : 1.0;
  return s;
}

void TabletInput::pen_down(const PointerSample& sample, const PointerContext& context) {
  if (closed_) return;
  finish_open();
  Stroke s;
  s.layer = context.layer;
  s.view = context.view;
  s.view->dpi = params_.dpi;
  s.samples_are_pixels = true;
  s.draw_plane = context.draw_plane;
  s.workspace_scale =
      std::isfinite(context.workspace_scale) && context.workspace_scale > 0 ? context.workspace_scale
                                                                            : 1.0;
  open_ = std::move(s);
  pen_move(sample);
}

void TabletInput::pen_move(const PointerSample& sample) {
  if (!open_) return;
  if (!keep_sample(open_->samples, sample.pixel, params_.min_spacing_px)) return;
  Sample s = to_sample(sample);
  // Sample times must not decrease within a stroke either.
  if (!open_->samples.empty()) s.time = std::max(s.time, open_->samples.back().time);
  open_->samples.push_back(s);
}

void TabletInput::pen_up(const PointerSample& sample) {
  if (!open_) return;
  pen_move(sample);
  finish_open();
}

void TabletInput::finish_open() {
  if (!open_) return;
  Stroke s = std::move(*open_);
  open_.reset();
  std::vector<Vec3> points;
  for (const Sample& x : s.samples) points.push_back(x.position);
  if (s.samples.size() < 2 || polyline_length(points) < params_.min_length_px) return;
  s.id = next_id_++;
  const double end = s.samples.back().time;
  push(Event{end, StrokeEvent{std::move(s)}});
}

void TabletInput::command(const Event& event) {
  if (closed_) return;
  if (std::holds_alternative<StrokeEvent>(event.payload)) return;  // strokes come from the pen
  finish_open();
  push(event);
}

void TabletInput::close() {
  finish_open();
  closed_ = true;
}

const std::vector<Sample>& TabletInput::open_samples() const {
  static const std::vector<Sample> none;
  return open_ ? open_->samples : none;
}

}  // namespace sketchlab::tablet
