#pragma once
// Writes recordings (format: event_json.hpp). Live sessions append each event
// as it happens; every line is flushed, so a crash loses at most the stroke in
// progress.
#include <cstdio>
#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>

#include "sketchlab/recording/recording.hpp"

namespace sketchlab {

class RecordingWriter {
 public:
  // Creates `path` and writes the header line. Throws std::runtime_error when
  // the file exists and !overwrite, or cannot be created; std::invalid_argument
  // for an invalid header.
  RecordingWriter(const std::filesystem::path& path, const RecordingHeader& header,
                  bool overwrite = false);
  ~RecordingWriter();
  RecordingWriter(const RecordingWriter&) = delete;
  RecordingWriter& operator=(const RecordingWriter&) = delete;

  // Writes one line and flushes. Throws std::invalid_argument (writing
  // nothing) for an event the reader would reject, including one earlier than
  // the previous event; std::runtime_error on an I/O failure or after close().
  void append(const Event& event);

  // Flushes and closes; further appends throw. Called by the destructor.
  void close();

  const std::filesystem::path& path() const { return path_; }
  std::size_t lines_written() const { return lines_; }

 private:
  std::filesystem::path path_;
  std::FILE* file_ = nullptr;
  std::size_t lines_ = 0;
  std::optional<double> last_time_;
  void write_line(const std::string& line);
};

// The whole recording as text (header line, then one line per event).
// Throws std::invalid_argument like RecordingWriter::append.
void write_recording(std::ostream& out, const Recording& recording);
// Same to a file; refuses to replace an existing file unless overwrite.
void write_recording(const std::filesystem::path& path, const Recording& recording,
                     bool overwrite = false);

}  // namespace sketchlab
