#include "sketchlab/recording/recording_reader.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "json_codec.hpp"
#include "sketchlab/io/warning.hpp"
#include "sketchlab/recording/event_json.hpp"

namespace sketchlab {

namespace {

std::string format_time(double t) { return json_codec::json(t).dump(); }

Recording parse_text(const std::string& text, const std::string& name,
                     const RecordingReadOptions& options) {
  if (text.empty()) {
    throw RecordingError(name, 0, "empty file: expected the header line {\"format\":\"sketchlab-recording\",...}");
  }
  Recording rec;
  std::optional<double> last_time;
  std::size_t line_no = 0;
  std::size_t pos = 0;
  while (pos < text.size()) {
    ++line_no;
    const std::size_t nl = text.find('\n', pos);
    const bool terminated = nl != std::string::npos;
    const std::string_view line(text.data() + pos, (terminated ? nl : text.size()) - pos);
    pos = terminated ? nl + 1 : text.size();
    try {
      // A writer ends every line with '\n', so a missing newline means the
      // write was interrupted. A header cut short leaves nothing to read.
      if (!terminated && (options.refuse_truncated || line_no == 1)) {
        std::string why = "truncated: the last line has no terminating newline (interrupted write?)";
        try {
          json_codec::parse_line(line);
        } catch (const std::invalid_argument&) {
          why += " and is not complete JSON";
        }
        throw std::invalid_argument(why);
      }
      if (line.empty() || line == "\r") {
        throw std::invalid_argument("empty line (every line must hold the header or one event)");
      }
      if (line_no == 1) {
        rec.header = header_from_json_line(line);
        continue;
      }
      std::optional<Event> e;
      try {
        e = event_from_json_line(line);
      } catch (const std::invalid_argument& why) {
        if (terminated) throw;
        warn(RecordingError(name, line_no,
                            std::string("skipped the last line: it has no terminating newline and "
                                        "does not read as an event (an interrupted write?): ") +
                                why.what())
                 .what());
        break;
      }
      if (last_time && e->time < *last_time) {
        throw std::invalid_argument("event time " + format_time(e->time) +
                                    " is earlier than the previous event's " +
                                    format_time(*last_time) + "; recordings are in time order");
      }
      if (!terminated)
        warn(RecordingError(name, line_no, "the last line has no terminating newline; its event is complete and kept").what());
      last_time = e->time;
      rec.events.push_back(std::move(*e));
    } catch (const std::invalid_argument& e) {
      throw RecordingError(name, line_no, e.what());
    }
  }
  return rec;
}

}  // namespace

Recording parse_recording(std::istream& in, const std::string& name,
                          const RecordingReadOptions& options) {
  std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (in.bad()) throw RecordingError(name, 0, "read failed");
  return parse_text(text, name, options);
}

Recording read_recording(const std::filesystem::path& path, const RecordingReadOptions& options) {
  const std::string name = path.string();
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw RecordingError(name, 0, "no such file");
  if (std::filesystem::is_directory(path, ec)) throw RecordingError(name, 0, "is a directory, not a recording");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw RecordingError(name, 0, std::string("cannot open: ") + std::strerror(errno));
  return parse_recording(in, name, options);
}

}  // namespace sketchlab
