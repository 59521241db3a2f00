#include "correction_worker.hpp"

#include <stdexcept>

namespace sketchlab::vr {

CorrectionWorker::CorrectionWorker(std::unique_ptr<LiveSession> live, Prepare prepare)
    : live_(std::move(live)), prepare_(std::move(prepare)) {
  if (!live_) throw std::invalid_argument("CorrectionWorker: no session");
  constraints_.resize(live_->stack_count());
  latest_ = snapshot(0);
  thread_ = std::thread([this] { run(); });
}

std::shared_ptr<const SketchSnapshot> CorrectionWorker::snapshot(std::uint64_t version) const {
  auto snap = std::make_shared<SketchSnapshot>();
  for (std::size_t i = 0; i < live_->stack_count(); ++i)
    snap->stacks.push_back({live_->session(i).sketch(), constraints_[i]});
  snap->stroke = stroke_;
  snap->strokes = strokes_;
  snap->events = live_->events_recorded();
  snap->version = version;
  if (prepare_) prepare_(*snap);
  return snap;
}

CorrectionWorker::~CorrectionWorker() {
  try {
    finish();
  } catch (...) {
  }
}

void CorrectionWorker::submit(Event event) {
  {
    std::lock_guard lock(mutex_);
    if (stopping_) throw std::logic_error("CorrectionWorker: submit after finish");
    queue_.push_back(std::move(event));
  }
  wake_.notify_one();
}

std::shared_ptr<const SketchSnapshot> CorrectionWorker::latest() const {
  std::lock_guard lock(mutex_);
  return latest_;
}

std::vector<std::string> CorrectionWorker::problems() const {
  std::lock_guard lock(mutex_);
  return problems_;
}

std::shared_ptr<const SketchSnapshot> CorrectionWorker::finish() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_one();
  if (thread_.joinable()) {
    thread_.join();
    live_->close();
  }
  return latest();
}

void CorrectionWorker::run() {
  std::uint64_t version = 0;
  for (;;) {
    Event event;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [&] { return stopping_ || !queue_.empty(); });
      if (queue_.empty()) return;  // stopping and drained
      event = std::move(queue_.front());
      queue_.pop_front();
    }
    // Counted whether or not the stroke is recorded: the viewer waits for
    // this count to stop showing the stroke as pending.
    if (const auto* s = std::get_if<StrokeEvent>(&event.payload)) {
      for (auto& c : constraints_) c.clear();
      stroke_ = s->stroke.id;
      ++strokes_;
    }
    std::string problem;
    try {
      const std::vector<StepReport> reports = live_->handle(event);
      for (const StepReport& r : reports)
        if (!r.error.empty()) problem = std::string(to_string(r.event)) + " at " + std::to_string(event.time) + " s: " + r.error;
      if (std::holds_alternative<StrokeEvent>(event.payload))
        for (std::size_t i = 0; i < reports.size(); ++i) constraints_[i] = reports[i].constraints;
    } catch (const std::exception& e) {
      problem = std::string(event_type_name(event.payload)) + " at " + std::to_string(event.time) +
                " s not recorded: " + e.what();
    }
    bool idle;
    {
      std::lock_guard lock(mutex_);
      idle = queue_.empty();
      if (!problem.empty()) problems_.push_back(problem);
    }
    // Copying the sketch only when caught up keeps a backlog from growing.
    if (idle) {
      try {
        auto snap = snapshot(++version);
        std::lock_guard lock(mutex_);
        latest_ = std::move(snap);
      } catch (const std::exception& e) {
        std::lock_guard lock(mutex_);
        problems_.push_back("preparing the view after " + std::string(event_type_name(event.payload)) + " at " +
                            std::to_string(event.time) + " s: " + e.what());
      }
    }
  }
}

}  // namespace sketchlab::vr
