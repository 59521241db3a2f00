#pragma once
// VTK's X render window aborts the process when it cannot open the display;
// check first and turn that into an error a caller can report.
#include <string>

namespace sketchlab::viewer {

// Empty when $DISPLAY is set and an X server accepts a connection there,
// else the reason with the remedy ("no X display: run under xvfb-run ...").
std::string display_problem();

// Throws std::runtime_error(display_problem()) when it is not empty.
void require_display();

// A connection to $DISPLAY held while VTK renders. An X server started
// without -noreset (xvfb-run's default) resets when its last client leaves,
// and a connection attempted during the reset is refused, which makes VTK
// abort; holding one open keeps the server up, and opening it retries
// briefly to ride out a reset in progress. Throws std::runtime_error with
// display_problem()'s message when there is no display.
class DisplayConnection {
 public:
  DisplayConnection();
  ~DisplayConnection();
  DisplayConnection(const DisplayConnection&) = delete;
  DisplayConnection& operator=(const DisplayConnection&) = delete;

 private:
  void* display_ = nullptr;  // Display*, kept opaque so callers need no Xlib
};

}  // namespace sketchlab::viewer
