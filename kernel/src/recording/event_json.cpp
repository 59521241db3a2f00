#include "sketchlab/recording/event_json.hpp"

#include <stdexcept>

#include "json_codec.hpp"
#include "sketchlab/curve.hpp"
#include "sketchlab/stroke.hpp"

namespace sketchlab {

std::string to_json_line(const Event& event) {
  // Name invalid strokes and curves the way validate() does before the
  // generic check below (which would only see NaN written as null).
  if (const auto* s = std::get_if<StrokeEvent>(&event.payload)) {
    if (const std::string why = validate(s->stroke); !why.empty()) throw std::invalid_argument(why);
  }
  if (const auto* r = std::get_if<ReferenceEvent>(&event.payload)) {
    if (const std::string why = validate(r->curve); !why.empty()) {
      throw std::invalid_argument("reference curve for stroke " + std::to_string(r->stroke) + ": " + why);
    }
  }
  std::string line = json_codec::to_json(event).dump();
  // Reading the line back applies every check the reader makes (non-finite
  // numbers would have been written as null), so nothing unreadable is written.
  event_from_json_line(line);
  return line;
}

std::string to_json_line(const RecordingHeader& header) {
  std::string line = json_codec::to_json(header).dump();
  header_from_json_line(line);
  return line;
}

Event event_from_json_line(std::string_view line) {
  return json_codec::event_from_json(json_codec::parse_line(line));
}

RecordingHeader header_from_json_line(std::string_view line) {
  return json_codec::header_from_json(json_codec::parse_line(line));
}

}  // namespace sketchlab
