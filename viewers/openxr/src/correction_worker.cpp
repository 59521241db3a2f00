#include "correction_worker.hpp"

#include <stdexcept>

namespace sketchlab::vr {

CorrectionWorker::CorrectionWorker(std::unique_ptr<LiveSession> live, std::size_t shown)
    : live_(std::move(live)), shown_(shown) {
  if (!live_ || shown_ >= live_->stack_count())
    throw std::invalid_argument("CorrectionWorker: no session or no stack " + std::to_string(shown));
  auto first = std::make_shared<SketchSnapshot>();
  first->sketch = live_->session(shown_).sketch();
  latest_ = first;
  thread_ = std::thread([this] { run(); });
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
    std::string problem;
    try {
      for (const StepReport& r : live_->handle(event))
        if (!r.error.empty()) problem = r.event + " at " + std::to_string(event.time) + " s: " + r.error;
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
      auto snap = std::make_shared<SketchSnapshot>();
      snap->sketch = live_->session(shown_).sketch();
      snap->events = live_->events_recorded();
      snap->version = ++version;
      std::lock_guard lock(mutex_);
      latest_ = std::move(snap);
    }
  }
}

}  // namespace sketchlab::vr
