#pragma once
// What the event parser says about one JSON line: its error message, or ""
// when it accepts the line.
#include <stdexcept>
#include <string>

#include "sketchlab/recording/event_json.hpp"

namespace sketchlab::test {

inline std::string event_line_error(const std::string& line) {
  try {
    event_from_json_line(line);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

}  // namespace sketchlab::test
