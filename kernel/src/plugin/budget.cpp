#include "sketchlab/plugin/budget.hpp"

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace sketchlab {

namespace {

using Clock = std::chrono::steady_clock;

// seconds == 0: no budget open on this thread.
thread_local Clock::time_point t_deadline{};
thread_local double t_seconds = 0.0;

}  // namespace

std::string BudgetExceeded::message() const {
  std::ostringstream text;
  text << "time budget of " << seconds << " s exceeded";
  return text.str();
}

void check_budget() {
  if (t_seconds > 0.0 && Clock::now() >= t_deadline) throw BudgetExceeded{t_seconds};
}

double budget_left() {
  if (!(t_seconds > 0.0)) return std::numeric_limits<double>::infinity();
  return std::chrono::duration<double>(t_deadline - Clock::now()).count();
}

BudgetScope::BudgetScope(double seconds)
    : previous_deadline_(t_deadline), previous_seconds_(t_seconds) {
  if (!(seconds > 0.0)) throw std::invalid_argument("BudgetScope: seconds must be > 0");
  // Beyond ~30 years a deadline would overflow the clock: treat as none.
  if (!std::isfinite(seconds) || seconds > 1e9) {
    t_seconds = 0.0;
    return;
  }
  t_seconds = seconds;
  t_deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                  std::chrono::duration<double>(seconds));
}

BudgetScope::~BudgetScope() {
  t_deadline = previous_deadline_;
  t_seconds = previous_seconds_;
}

}  // namespace sketchlab
