#include "sketchlab/viewer/display.hpp"

#include <X11/Xlib.h>

#include <chrono>
#include <cstdlib>
#include <stdexcept>
#include <thread>

namespace sketchlab::viewer {
namespace {

const char* const kNoDisplay =
    "no X display: run under xvfb-run (e.g. `xvfb-run -a sketchlab render ...`) or set DISPLAY "
    "to a running X server or Xvfb; Debian's VTK renders offscreen through X";

// Opens $DISPLAY, retrying for about a second (a server may be resetting).
// Null with the reason in `problem` when it cannot.
Display* open_display(std::string& problem) {
  const char* name = std::getenv("DISPLAY");
  if (!name || !*name) {
    problem = kNoDisplay;
    return nullptr;
  }
  for (int attempt = 0; attempt < 20; ++attempt) {
    if (Display* display = XOpenDisplay(name)) return display;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  problem = std::string("no X display: cannot connect to DISPLAY=") + name +
            "; run under xvfb-run (e.g. `xvfb-run -a sketchlab render ...`) or start Xvfb there";
  return nullptr;
}

}  // namespace

std::string display_problem() {
  std::string problem;
  if (Display* display = open_display(problem)) XCloseDisplay(display);
  return problem;
}

void require_display() {
  if (std::string problem = display_problem(); !problem.empty())
    throw std::runtime_error(problem);
}

DisplayConnection::DisplayConnection() {
  std::string problem;
  display_ = open_display(problem);
  if (!display_) throw std::runtime_error(problem);
}

DisplayConnection::~DisplayConnection() {
  if (display_) XCloseDisplay(static_cast<Display*>(display_));
}

}  // namespace sketchlab::viewer
