#include "sketchlab/recording/recording_writer.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <ostream>
#include <sstream>
#include <stdexcept>

#include "json_codec.hpp"
#include "sketchlab/recording/event_json.hpp"

namespace sketchlab {

namespace {

std::string format_time(double t) { return json_codec::json(t).dump(); }

void check_order(const std::optional<double>& last, const Event& e) {
  if (last && e.time < *last) {
    throw std::invalid_argument("event time " + format_time(e.time) +
                                " is earlier than the previous event's " + format_time(*last) +
                                "; recordings are in time order");
  }
}

}  // namespace

RecordingWriter::RecordingWriter(const std::filesystem::path& path, const RecordingHeader& header,
                                 bool overwrite)
    : path_(path) {
  const std::string line = to_json_line(header);  // validates before touching the disk
  // "x" (C11) creates exclusively: no race between an existence check and the open.
  file_ = std::fopen(path.c_str(), overwrite ? "wb" : "wbx");
  if (!file_) {
    const int err = errno;
    if (!overwrite && err == EEXIST) {
      throw std::runtime_error(path.string() +
                               ": already exists; refusing to overwrite a recording (pass "
                               "overwrite = true to replace it)");
    }
    throw std::runtime_error(path.string() + ": cannot create: " + std::strerror(err));
  }
  write_line(line);
}

RecordingWriter::~RecordingWriter() {
  if (file_) std::fclose(file_);
}

void RecordingWriter::write_line(const std::string& line) {
  if (!file_) throw std::runtime_error(path_.string() + ": the recording writer is closed");
  const std::string text = line + "\n";
  if (std::fwrite(text.data(), 1, text.size(), file_) != text.size() || std::fflush(file_) != 0) {
    throw std::runtime_error(path_.string() + ": write failed: " + std::strerror(errno));
  }
  ++lines_;
}

void RecordingWriter::append(const Event& event) {
  check_order(last_time_, event);
  write_line(to_json_line(event));
  last_time_ = event.time;
}

void RecordingWriter::close() {
  if (!file_) return;
  const int rc = std::fclose(file_);
  file_ = nullptr;
  if (rc != 0) throw std::runtime_error(path_.string() + ": close failed: " + std::strerror(errno));
}

void write_recording(std::ostream& out, const Recording& recording) {
  // Serialise everything first so an invalid event leaves `out` untouched.
  std::string text = to_json_line(recording.header) + "\n";
  std::optional<double> last;
  for (const Event& e : recording.events) {
    check_order(last, e);
    text += to_json_line(e);
    text += '\n';
    last = e.time;
  }
  out << text;
  out.flush();
  if (!out) throw std::runtime_error("write_recording: stream write failed");
}

void write_recording(const std::filesystem::path& path, const Recording& recording, bool overwrite) {
  std::optional<double> last;
  for (const Event& e : recording.events) {  // fail before creating the file
    check_order(last, e);
    to_json_line(e);
    last = e.time;
  }
  RecordingWriter writer(path, recording.header, overwrite);
  for (const Event& e : recording.events) writer.append(e);
  writer.close();
}

}  // namespace sketchlab
