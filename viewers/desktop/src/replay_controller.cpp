#include "sketchlab/desktop/replay_controller.hpp"

#include <algorithm>
#include <stdexcept>

namespace sketchlab::desktop {

ReplayController::ReplayController(Recording recording, const std::vector<StackInstance>& stacks)
    : recording_(std::move(recording)) {
  if (stacks.empty()) throw std::invalid_argument("ReplayController: no stacks");
  for (const StackInstance& s : stacks)
    sessions_.emplace_back(recording_.header.workspace, s.corrector, s.surfacer);
  reports_.resize(stacks.size());
  stops_.push_back(0);
  for (std::size_t i = 0; i < recording_.events.size(); ++i)
    if (std::holds_alternative<StrokeEvent>(recording_.events[i].payload)) stops_.push_back(i + 1);
  if (stops_.back() != recording_.events.size()) stops_.push_back(recording_.events.size());
}

std::size_t ReplayController::stop_index() const {
  const auto it = std::upper_bound(stops_.begin(), stops_.end(), position_);
  return static_cast<std::size_t>(it - stops_.begin()) - 1;
}

void ReplayController::seek(std::size_t event_index) {
  event_index = std::min(event_index, recording_.events.size());
  while (position_ < event_index) {
    const Event& e = recording_.events[position_];
    for (std::size_t s = 0; s < sessions_.size(); ++s) reports_[s].push_back(sessions_[s].handle(e));
    ++position_;
  }
  while (position_ > event_index) {
    for (std::size_t s = 0; s < sessions_.size(); ++s) {
      if (!sessions_[s].revert_last())
        throw std::logic_error("ReplayController: session has fewer events than the position");
      reports_[s].pop_back();
    }
    --position_;
  }
}

void ReplayController::seek_stop(std::size_t stop) {
  seek(stops_.at(std::min(stop, stops_.size() - 1)));
}

bool ReplayController::step_forward() {
  const auto it = std::upper_bound(stops_.begin(), stops_.end(), position_);
  if (it == stops_.end()) return false;
  seek(*it);
  return true;
}

bool ReplayController::step_back() {
  if (position_ == 0) return false;
  const auto it = std::lower_bound(stops_.begin(), stops_.end(), position_);
  seek(*(it - 1));
  return true;
}

const StepReport* ReplayController::last_stroke_report(std::size_t stack) const {
  const auto& r = reports_.at(stack);
  for (auto it = r.rbegin(); it != r.rend(); ++it)
    if (it->stroke && it->event == EventKind::stroke) return &*it;
  return nullptr;
}

}  // namespace sketchlab::desktop
