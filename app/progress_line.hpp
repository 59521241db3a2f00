#pragma once
// A one-line progress display: cases done and failed, the current case and
// an ETA (over every rank of a distributed run: rank 0 draws it).
// Debian packages no C++ progress-bar library, and this needs only a
// carriage return. On a terminal the line is redrawn in place; otherwise one
// line is printed per finished case (logs stay readable).
#include <ostream>

#include "sketchlab/lab/experiment_runner.hpp"

namespace sketchlab::cli {

class ProgressLine {
 public:
  ProgressLine(std::ostream& out, bool interactive) : out_(out), interactive_(interactive) {}
  void update(const Progress& p);
  void finish();

 private:
  std::ostream& out_;
  bool interactive_;
  std::size_t last_done_ = 0;
  bool drawn_ = false;
};

}  // namespace sketchlab::cli
