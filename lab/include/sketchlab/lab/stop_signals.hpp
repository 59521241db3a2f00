#pragma once
// Ending a long-running command cleanly (`sketchlab record`, `sketchlab vr`):
// while a StopSignals lives, SIGINT (Ctrl-C) and SIGTERM (kill, a service
// manager) no longer kill the process; they set stop_requested(), which the
// command's loop polls to finish what is in progress, close its recording and
// print its figures. The previous handlers come back when it is destroyed.
namespace sketchlab {

class StopSignals {
 public:
  StopSignals();
  ~StopSignals();
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;

  // The signal received since construction (0: none).
  static int received();
  static bool stop_requested() { return received() != 0; }

 private:
  void (*previous_int_)(int);
  void (*previous_term_)(int);
};

}  // namespace sketchlab
