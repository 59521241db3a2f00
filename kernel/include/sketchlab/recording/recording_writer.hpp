#pragma once
// Writes recordings (format: event_json.hpp). Live sessions append each event
// as it happens. Each line goes to the file in one write(2) (continued only
// after a short write), so a crash loses at most the stroke in progress; a
// process killed inside that call can leave a partial last line, which the
// reader skips with a warning. A failed write (disk full, file size limit)
// is cut back off the file before the error is thrown: the file then still
// ends with a complete line and later appends may succeed.
#include <cstdint>
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

  // Writes one line. Throws std::invalid_argument (writing nothing) for an
  // event the reader would reject, including one earlier than the previous
  // event; std::runtime_error on an I/O failure (the partial line removed
  // again; when even that fails the writer closes, leaving the partial line
  // last) or after close().
  void append(const Event& event);

  // Closes; further appends throw. Called by the destructor.
  void close();

  const std::filesystem::path& path() const { return path_; }
  std::size_t lines_written() const { return lines_; }
  // Bytes of complete lines in the file.
  std::uint64_t bytes_written() const { return bytes_; }

 private:
  std::filesystem::path path_;
  int fd_ = -1;
  std::size_t lines_ = 0;
  std::uint64_t bytes_ = 0;
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
