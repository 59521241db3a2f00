#include "sketchlab/desktop/viewer_model.hpp"

#include <algorithm>
#include <stdexcept>

namespace sketchlab::desktop {

ViewerModel::ViewerModel(std::vector<StackInstance> stacks, std::optional<Recording> replay,
                         RecordingHeader live_header, std::filesystem::path record_path,
                         bool overwrite)
    : stacks_(std::move(stacks)),
      live_header_(std::move(live_header)),
      record_path_(std::move(record_path)),
      overwrite_(overwrite) {
  if (stacks_.empty()) throw std::invalid_argument("viewer: the config has no stacks");
  // An empty replay keeps sketch() uniform before anything is drawn.
  Recording r = replay ? std::move(*replay) : Recording{live_header_, {}};
  replay_ = std::make_unique<ReplayController>(std::move(r), stacks_);
  live_reports_.resize(stacks_.size());
}

const Sketch& ViewerModel::sketch(std::size_t stack) const {
  return live_ ? live_->session(stack).sketch() : replay_->session(stack).sketch();
}

const StepReport* ViewerModel::last_stroke_report(std::size_t stack) const {
  if (!live_) return replay_->last_stroke_report(stack);
  const auto& r = live_reports_.at(stack);
  return r ? &*r : nullptr;
}

std::vector<StepReport> ViewerModel::handle_live(const Event& event) {
  if (!live_) {
    const Recording& rec = replay_->recording();
    auto live = std::make_unique<LiveSession>(rec.header, stacks_, record_path_, overwrite_);
    const std::size_t n = replay_->position();
    for (std::size_t i = 0; i < n; ++i) {
      const auto reports = live->handle(rec.events[i]);
      if (std::holds_alternative<StrokeEvent>(rec.events[i].payload))
        for (std::size_t s = 0; s < reports.size(); ++s) live_reports_[s] = reports[s];
      live_events_.push_back(rec.events[i]);
    }
    live_ = std::move(live);
    replay_.reset();
  }
  auto reports = live_->handle(event);
  live_events_.push_back(event);
  if (std::holds_alternative<StrokeEvent>(event.payload))
    for (std::size_t s = 0; s < reports.size(); ++s) live_reports_[s] = reports[s];
  return reports;
}

Recording ViewerModel::events() const {
  if (live_) return Recording{live_->header(), live_events_};
  const Recording& rec = replay_->recording();
  return Recording{rec.header, std::vector<Event>(rec.events.begin(),
                                                  rec.events.begin() + static_cast<std::ptrdiff_t>(
                                                                           replay_->position()))};
}

double ViewerModel::last_time() const {
  if (live_) return live_events_.empty() ? 0.0 : live_events_.back().time;
  const std::size_t p = replay_->position();
  return p == 0 ? 0.0 : replay_->recording().events[p - 1].time;
}

StrokeId ViewerModel::next_stroke_id() const {
  StrokeId next = 1;
  const Recording r = events();
  for (const Event& e : r.events)
    if (const auto* s = std::get_if<StrokeEvent>(&e.payload)) next = std::max(next, s->stroke.id + 1);
  return next;
}

}  // namespace sketchlab::desktop
