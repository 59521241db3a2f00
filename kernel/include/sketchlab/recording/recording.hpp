#pragma once
// A recording in memory: its header line and its events, in file order.
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "sketchlab/event.hpp"

namespace sketchlab {

struct Recording {
  RecordingHeader header;
  std::vector<Event> events;  // non-decreasing in time
  bool operator==(const Recording&) const = default;
};

// A recording that cannot be read. what() is "file:line: reason" (or
// "file: reason" when line is 0, i.e. the problem concerns the whole file).
class RecordingError : public std::runtime_error {
 public:
  RecordingError(std::string file, std::size_t line, std::string reason);

  std::string file;    // path or stream name as given
  std::size_t line;    // 1-based; the header is line 1; 0 = whole file
  std::string reason;  // the message without the location
};

}  // namespace sketchlab
