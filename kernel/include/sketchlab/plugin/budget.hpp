#pragma once
// The time budget of one event (issue 17): how long a stack may spend on a
// stroke before the stroke is given up. The Session opens a BudgetScope
// around its calls into the corrector and surfacer for each event. Plugins
// honour it by calling check_budget() at the head of their long loops
// (candidate searches, solver rounds, cycle searches, refinement passes); a
// check is one clock read, so a few per loop iteration cost nothing. When the
// time is up check_budget() throws BudgetExceeded; the plugin wrappers
// (plugin_api.hpp) turn it into that call's error and the Session reports it
// as the event's error ("time budget of 60 s exceeded"), keeping the raw
// stroke and the rest of the session.
//
// The budget belongs to the thread that opened it: checks made on other
// threads (a plugin's own worker pool) see none and never throw.
#include <chrono>
#include <string>

namespace sketchlab {

// Seconds per event when the stack sets none (stack key `time_budget`): far
// above any bundled stroke (the slowest takes well under a second), so only a
// runaway computation meets it.
inline constexpr double default_time_budget_s = 60.0;

// Thrown by check_budget(). Deliberately not a std::exception: a plugin's
// catch (const std::exception&) around a fallible step must not swallow it.
struct BudgetExceeded {
  double seconds = 0.0;  // the budget that ran out
  std::string message() const;  // "time budget of 2 s exceeded"
};

// Throws BudgetExceeded when the calling thread's budget has run out; does
// nothing when none is open.
void check_budget();
// Seconds left in the calling thread's budget (+infinity when none is open).
double budget_left();

// Opens a budget of `seconds` (> 0; +infinity for none) on the calling
// thread until destroyed; the scope it replaced is restored then.
class BudgetScope {
 public:
  explicit BudgetScope(double seconds);
  ~BudgetScope();
  BudgetScope(const BudgetScope&) = delete;
  BudgetScope& operator=(const BudgetScope&) = delete;

 private:
  std::chrono::steady_clock::time_point previous_deadline_;
  double previous_seconds_;
};

}  // namespace sketchlab
