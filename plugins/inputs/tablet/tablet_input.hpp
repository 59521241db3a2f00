#pragma once
// The tablet / mouse input: pointer events pushed by a window become 2D
// strokes (pixels + the View at pen-down, timestamps, pressure) and commands,
// handed out in order by next().
#include <deque>
#include <optional>

#include "sketchlab/plugin/pointer_input.hpp"

namespace sketchlab::tablet {

struct TabletParams {
  double min_length_px = 3.0;     // shorter strokes are clicks: dropped
  double min_spacing_px = 0.5;    // moves closer than this to the last sample are skipped
  double dpi = 96.0;              // pixels per inch of the surface (View::dpi)
  Vec3 up = Vec3::UnitY();        // workspace up axis for the header
};

class TabletInput : public PointerInput {
 public:
  explicit TabletInput(const TabletParams& params);

  RecordingHeader header() const override;
  NextEvent next() override;

  void pen_down(const PointerSample& sample, const PointerContext& context) override;
  void pen_move(const PointerSample& sample) override;
  void pen_up(const PointerSample& sample) override;
  void cancel() override { open_.reset(); }
  void command(const Event& event) override;
  void set_next_stroke_id(StrokeId id) override { next_id_ = id; }
  void close() override;

  bool drawing() const { return open_.has_value(); }
  // The samples of the stroke being drawn (empty when none), for live feedback.
  const std::vector<Sample>& open_samples() const;

 private:
  void push(Event event);
  void finish_open();

  TabletParams params_;
  std::optional<Stroke> open_;
  std::deque<Event> queue_;
  StrokeId next_id_ = 1;
  double last_time_ = 0.0;
  bool closed_ = false;
};

// A sample is kept when finite and at least `min_spacing` pixels from the
// previous kept one (the first always is).
bool keep_sample(const std::vector<Sample>& kept, const Vec2& pixel, double min_spacing);

}  // namespace sketchlab::tablet
