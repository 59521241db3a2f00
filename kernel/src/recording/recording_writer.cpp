#include "sketchlab/recording/recording_writer.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <ostream>
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
  // O_EXCL creates exclusively: no race between an existence check and the
  // open. O_APPEND: after a failed line is cut off, the next one starts at the
  // new end.
  fd_ = ::open(path.c_str(), O_WRONLY | O_APPEND | O_CREAT | O_CLOEXEC | (overwrite ? O_TRUNC : O_EXCL), 0644);
  if (fd_ < 0) {
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
  if (fd_ >= 0) ::close(fd_);
}

void RecordingWriter::write_line(const std::string& line) {
  if (fd_ < 0) throw std::runtime_error(path_.string() + ": the recording writer is closed");
  const std::string text = line + "\n";
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd_, text.data() + done, text.size() - done);
    if (n > 0) {
      done += static_cast<std::size_t>(n);
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    const int err = n < 0 ? errno : ENOSPC;
    std::string what = path_.string() + ": write failed after " + std::to_string(done) + " of " +
                       std::to_string(text.size()) + " bytes of line " + std::to_string(lines_ + 1) +
                       ": " + std::strerror(err);
    // Cut the partial line off so that the file still ends with a complete
    // line; where that fails, stop writing so the partial line stays last.
    if (done > 0 && ::ftruncate(fd_, static_cast<off_t>(bytes_)) != 0) {
      what += "; the partial line could not be removed (" + std::string(std::strerror(errno)) +
              "), so the writer is closed (readers skip a partial last line)";
      ::close(fd_);
      fd_ = -1;
    }
    throw std::runtime_error(what);
  }
  bytes_ += text.size();
  ++lines_;
}

void RecordingWriter::append(const Event& event) {
  check_order(last_time_, event);
  write_line(to_json_line(event));
  last_time_ = event.time;
}

void RecordingWriter::close() {
  if (fd_ < 0) return;
  const int rc = ::close(fd_);
  fd_ = -1;
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
