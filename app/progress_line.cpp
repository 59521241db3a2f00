#include "progress_line.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace sketchlab::cli {
namespace {

std::string clock_text(double seconds) {
  const long s = std::lround(seconds);
  std::ostringstream o;
  o << s / 60 << ":" << (s % 60 < 10 ? "0" : "") << s % 60;
  return o.str();
}

}  // namespace

void ProgressLine::update(const Progress& p) {
  // Cases finished before a --resume were not finished now.
  const bool finished_one = p.done > std::max(last_done_, p.resumed);
  last_done_ = p.done;
  std::ostringstream line;
  const int width = 24;
  const int filled = p.total ? static_cast<int>(width * p.done / p.total) : width;
  line << "[" << std::string(filled, '#') << std::string(width - filled, ' ') << "] " << p.done << "/"
       << p.total << " cases";
  if (p.failed) line << ", " << p.failed << " failed";
  // The rate of this run alone: cases finished before a --resume took no time.
  if (p.done > p.resumed && p.done < p.total)
    line << ", ETA " << clock_text(p.elapsed_s / static_cast<double>(p.done - p.resumed) * static_cast<double>(p.total - p.done));
  line << "  " << (finished_one ? "done: " : "running: ") << p.current;
  if (interactive_) {
    out_ << "\r\033[K" << line.str() << std::flush;
    drawn_ = true;
  } else if (finished_one) {
    out_ << line.str() << "\n";
  }
}

void ProgressLine::finish() {
  if (drawn_) out_ << "\n";
  drawn_ = false;
}

}  // namespace sketchlab::cli
